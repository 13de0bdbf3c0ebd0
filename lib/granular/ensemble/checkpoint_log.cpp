#include "granular/ensemble/checkpoint_log.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "granular/code_identity.hpp"
#include "granular/error.hpp"
#include "granular/io/detail/temporary_file.hpp"
#include "granular/io/text_hash.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

constexpr const char* magic = "granular-checkpoint 1 ";
constexpr const char* version_key = "granular_version";
constexpr const char* commit_key = "granular_commit";
// Every code whose realizations the log holds, oldest first, when more than one did (a resume
// accepted across versions); absent when the code of version_key/commit_key made them all.
constexpr const char* contributors_key = "granular_contributors";

/// A hash of the record's text: catches a torn or edited line. Its basis, a digit short of FNV's
/// offset basis since the format's first version, is part of the format: with another, every line
/// of an existing checkpoint would read as torn and be computed again.
std::uint64_t checksum(std::string_view text) { return text_hash(text, 1469598103934665603ull); }

/// One record line, newline included.
std::string format_record(std::uint64_t index, const std::vector<double>& values) {
  std::string body = std::to_string(index);
  body.push_back(' ');
  body.append(std::to_string(values.size()));
  for (double v : values) {
    body.push_back(' ');
    body.append(format_number(v));
  }
  const std::string sum = std::to_string(checksum(body));
  body.push_back(' ');
  body.append(sum);
  body.push_back('\n');
  return body;
}

bool same_json(const std::string& a, const std::string& b) {
  try {
    return nlohmann::json::parse(a) == nlohmann::json::parse(b);
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

std::string first_difference(const std::string& a, const std::string& b) {
  try {
    const auto ja = nlohmann::json::parse(a), jb = nlohmann::json::parse(b);
    for (const auto& [key, value] : jb.items())
      if (!ja.contains(key) || ja[key] != value)
        return key + " (checkpoint: " + (ja.contains(key) ? ja[key].dump() : "absent") + ", now: " + value.dump() + ")";
    for (const auto& [key, value] : ja.items())
      if (!jb.contains(key)) return key + " (checkpoint: " + value.dump() + ", now: absent)";
  } catch (const nlohmann::json::exception&) {
  }
  return "the parameter header";
}

/// The header's JSON: the run's parameters with the code that made the records put in front
/// (the parameters' own text is kept byte for byte after it), and every code whose records it
/// holds when that is more than this one. Other text stays as it is.
std::string with_code(const std::string& parameters, const std::vector<std::string>& contributors = {}) {
  if (parameters.empty() || parameters.front() != '{') return parameters;
  nlohmann::json code = {{version_key, code_version()}, {commit_key, code_commit()}};
  if (contributors.size() > 1) code[contributors_key] = contributors;
  const std::string head = code.dump();  // {"granular_commit":"…","granular_version":"…"}
  const bool empty = parameters.find_first_not_of(" ", 1) == parameters.find('}');
  std::string out(head, 0, head.size() - 1);  // appended piece by piece: GCC 12 warns falsely on a + b + c
  if (empty) {
    out.push_back('}');
  } else {
    out.push_back(',');
    out.append(parameters, 1, std::string::npos);
  }
  return out;
}

/// Whether another code made a log with this header: another version, or the same version built
/// from another commit when both commits are known ("unknown" outside git cannot tell them apart).
/// The version alone is not enough: it changes with releases, the code with every commit.
bool made_by_other_code(const nlohmann::json& header) {
  if (!header.contains(version_key) || header[version_key] != code_version()) return true;
  const std::string ours = code_commit();
  if (ours == "unknown" || !header.contains(commit_key) || !header[commit_key].is_string()) return false;
  const std::string theirs = header[commit_key].get<std::string>();
  return theirs != "unknown" && theirs != ours;
}

/// "0.1.0 (commit 0123456789ab)"; "an unrecorded version" for a header written before versions were.
std::string code_named(const nlohmann::json& header) {
  if (!header.contains(version_key)) return "a granular version that did not record itself";
  std::string name =
      header[version_key].is_string() ? header[version_key].get<std::string>() : header[version_key].dump();
  if (header.contains(commit_key) && header[commit_key].is_string())
    name += " (commit " + header[commit_key].get<std::string>() + ")";
  return name;
}

/// The codes whose records a log with this header holds, oldest first: its list of contributors,
/// else the one code that wrote it.
std::vector<std::string> codes_in(const nlohmann::json& header) {
  if (header.contains(contributors_key) && header[contributors_key].is_array()) {
    std::vector<std::string> codes;
    for (const auto& c : header[contributors_key])
      if (c.is_string()) codes.push_back(c.get<std::string>());
    if (!codes.empty()) return codes;
  }
  return {code_named(header)};
}

/// `codes` with `code` appended unless it is there already.
std::vector<std::string> with_member(std::vector<std::string> codes, const std::string& code) {
  if (std::find(codes.begin(), codes.end(), code) == codes.end()) codes.push_back(code);
  return codes;
}

/// "checkpoint 'run.checkpoint' was made by granular 0.0.9 (commit …), this is granular 0.1.0 (commit …)"
std::string other_version_text(const std::string& path, const nlohmann::json& header) {
  return "checkpoint '" + path + "' was made by granular " + code_named(header) + ", this is granular " +
         CheckpointLog::this_code();
}

/// The JSON header of the checkpoint at `path`, or nothing when it is not one (or unreadable).
std::optional<nlohmann::json> header_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  if (line.compare(0, std::strlen(magic), magic) != 0) return std::nullopt;
  try {
    return nlohmann::json::parse(line.substr(std::strlen(magic)));
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace

CheckpointRecords CheckpointLog::parse_records(const std::string& text, std::string* header) {
  CheckpointRecords records;
  std::size_t begin = 0;
  bool first = true;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) break;  // torn last line
    const std::string_view line(text.data() + begin, end - begin);
    begin = end + 1;
    if (first) {
      first = false;
      if (line.substr(0, std::strlen(magic)) != magic) throw InvalidInput("not a granular checkpoint file");
      if (header) *header = std::string(line.substr(std::strlen(magic)));
      continue;
    }
    const std::size_t last_space = line.rfind(' ');
    if (last_space == std::string_view::npos) continue;
    const std::string_view body = line.substr(0, last_space), tail = line.substr(last_space + 1);
    std::uint64_t sum = 0;
    if (std::from_chars(tail.data(), tail.data() + tail.size(), sum).ec != std::errc() || sum != checksum(body))
      continue;
    std::vector<double> numbers;
    const char* p = body.data();
    const char* stop = body.data() + body.size();
    bool ok = true;
    std::uint64_t index = 0, count = 0;
    ok = std::from_chars(p, stop, index).ec == std::errc();
    if (ok) {
      p = std::find(p, stop, ' ');
      ok = p != stop;
    }
    if (ok) {
      ++p;
      ok = std::from_chars(p, stop, count).ec == std::errc();
      p = std::find(p, stop, ' ');
    }
    while (ok && p != stop) {
      ++p;
      double v = 0;
      auto [next, ec] = std::from_chars(p, stop, v);
      if (ec != std::errc()) {  // from_chars does not read "nan"/"inf" spelled by format_number
        const std::string_view word(p, static_cast<std::size_t>(std::find(p, stop, ' ') - p));
        if (word == "nan") v = std::numeric_limits<double>::quiet_NaN();
        else if (word == "inf") v = std::numeric_limits<double>::infinity();
        else if (word == "-inf") v = -std::numeric_limits<double>::infinity();
        else {
          ok = false;
          break;
        }
        next = p + word.size();
      }
      numbers.push_back(v);
      p = next;
    }
    if (ok && numbers.size() == count) records[index] = std::move(numbers);
  }
  return records;
}

CheckpointLog::CheckpointLog(std::string path, std::string parameters, const CheckpointRecords& records)
    : path_(std::move(path)) {
  // Written whole under a new temporary name (never through a symlink planted there), fsynced and
  // renamed, the folder fsynced: a kill never leaves a half header. The records are then appended
  // through the same descriptor, never by reopening the name.
  // The records carried over from the log being replaced keep their makers (a resume across
  // versions, accepted): the new header lists them with this code.
  std::vector<std::string> contributors;
  if (const auto old = records.empty() ? std::nullopt : header_of(path_); old && old->is_object())
    contributors = with_member(codes_in(*old), this_code());
  detail::TemporaryFile temporary(path_, "checkpoint ");
  std::string text = magic + with_code(parameters, contributors) + "\n";
  for (const auto& [index, values] : records) text += format_record(index, values);
  const char* p = text.data();
  const char* end = text.data() + text.size();
  while (p < end) {
    const ssize_t n = ::write(temporary.fd(), p, static_cast<std::size_t>(end - p));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw IoError("cannot write checkpoint '" + path_ + "': " + std::strerror(n < 0 ? errno : EIO));
    p += n;
  }
  const int fd = temporary.commit_open();
  file_ = ::fdopen(fd, "ab");
  if (!file_) {
    const int e = errno;
    ::close(fd);
    throw IoError("cannot append to checkpoint '" + path_ + "': " + std::strerror(e));
  }
}

CheckpointLog::~CheckpointLog() {
  if (file_) std::fclose(file_);
}

std::string CheckpointLog::rank_path(const std::string& base, int rank) {
  return rank == 0 ? base : base + ".rank" + std::to_string(rank);
}

namespace {

/// `base` and its rank logs (no case logs, no temporaries).
std::vector<std::string> family(const std::string& base) { return CheckpointLog::files(base, {}); }

}  // namespace

CheckpointRecords CheckpointLog::load(const std::string& base, const std::string& parameters, bool accept_other_version) {
  const auto logs = family(base);
  if (logs.empty()) {
    // A kill before the header's rename leaves only its temporary: the run had finished nothing.
    const bool started = !CheckpointLog::files(base, {.temporaries = true}).empty();
    throw InvalidInput("resume", ": no checkpoint '" + base + "' to resume from" +
                                     (started ? std::string(" (a run was stopped before it finished anything; start it "
                                                            "again without it)")
                                              : std::string()));
  }
  CheckpointRecords all;
  for (const std::string& path : logs) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError("cannot read checkpoint '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    std::string header;
    CheckpointRecords records;
    try {
      records = parse_records(text.str(), &header);
    } catch (const InvalidInput&) {
      throw InvalidInput("resume", ": '" + path + "' is not a checkpoint of this toolkit");
    }
    if (header != with_code(parameters)) {
      // Another code made it? Say so before comparing parameters (a new code may describe a run
      // differently): its realizations are not this code's, unless the user accepts that.
      std::string theirs = header;
      try {
        nlohmann::json recorded = nlohmann::json::parse(header);
        if (recorded.is_object() && made_by_other_code(recorded)) {
          if (!accept_other_version)
            throw InvalidInput("resume",
                               ": " + other_version_text(path, recorded) +
                                   "; resume it with the code that made it, or accept the mix (resume_other_version)");
        }
        if (recorded.is_object()) {
          recorded.erase(version_key);
          recorded.erase(commit_key);
          recorded.erase(contributors_key);
          theirs = recorded.dump();
        }
      } catch (const nlohmann::json::exception&) {
      }
      // Same code (or another, accepted): the parameters decide.
      if (theirs != parameters && !same_json(theirs, parameters))
        throw InvalidInput("resume", ": checkpoint '" + path + "' was made with different parameters: " +
                                         first_difference(theirs, parameters));
    }
    all.merge(records);
  }
  return all;
}

std::string CheckpointLog::other_version(const std::string& base) {
  for (const std::string& path : family(base))
    if (const auto header = header_of(path); header && header->is_object() && made_by_other_code(*header))
      return other_version_text(path, *header);
  return "";
}

std::string CheckpointLog::code_of(const std::string& base) {
  for (const std::string& path : family(base))
    if (const auto header = header_of(path)) return code_named(*header);
  return "";
}

std::vector<std::string> CheckpointLog::codes_of(const std::string& base) {
  std::vector<std::string> codes;
  for (const std::string& path : family(base))
    if (const auto header = header_of(path); header && header->is_object())
      for (const std::string& code : codes_in(*header)) codes = with_member(std::move(codes), code);
  return codes;
}

std::string CheckpointLog::this_code() { return code_named(nlohmann::json::parse(with_code("{}"))); }

bool CheckpointLog::exists(const std::string& base) { return !family(base).empty(); }

void CheckpointLog::settle(const std::string& base, bool discard, bool cases) {
  const std::vector<std::string> logs = files(base, {.cases = cases});
  if (logs.empty()) return;
  if (!discard)
    throw InvalidInput("checkpoint", " '" + logs.front() +
                                         "': holds the finished realizations of an interrupted run; continue it with "
                                         "`resume`, or discard them with `fresh`");
  for (const std::string& f : files(base, {.cases = cases, .temporaries = true})) std::filesystem::remove(f);
}

std::vector<std::string> CheckpointLog::files(const std::string& base, Members which) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(base).parent_path();
  const std::string stem = fs::path(base).filename().string();
  const auto member = [&](const std::string& name) {
    if (name.compare(0, stem.size(), stem) != 0) return false;
    std::size_t at = stem.size();
    const auto skip = [&](const std::string& tag) {  // tag followed by digits up to the next '.'
      const std::size_t end = std::min(name.find('.', at + tag.size()), name.size());
      if (name.compare(at, tag.size(), tag) != 0 || end == at + tag.size() ||
          name.find_first_not_of("0123456789", at + tag.size()) < end)
        return false;
      at = end;
      return true;
    };
    if (which.cases) skip(".");
    skip(".rank");
    if (which.temporaries) skip(".tmp.");
    return at == name.size();
  };
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder.empty() ? fs::path(".") : folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (member(name)) found.push_back((folder / name).string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

void CheckpointLog::remove_all(const std::string& base) {
  for (const std::string& path : family(base)) std::filesystem::remove(path);
  // A run killed between creating a header's temporary and renaming it leaves BASE[.rankK].tmp.PID
  // behind (io/detail/temporary_file); once the run is done it is nobody's.
  std::error_code ec;
  for (const std::string& path : files(base, {.temporaries = true})) std::filesystem::remove(path, ec);
}

void CheckpointLog::append(std::uint64_t index, const std::vector<double>& values) {
  const std::string line = format_record(index, values);
  std::lock_guard lock(mutex_);
  errno = 0;
  // A line cut short here (disk full) is torn: load() skips it, and a resumed run rewrites the log whole.
  if (!file_ || std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0 ||
      ::fdatasync(::fileno(file_)) != 0)
    throw IoError("cannot append to checkpoint '" + path_ + "': " + std::strerror(errno ? errno : EIO));
}

}  // namespace granular
