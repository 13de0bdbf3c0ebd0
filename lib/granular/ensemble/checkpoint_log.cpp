#include "granular/ensemble/checkpoint_log.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

constexpr const char* magic = "granular-checkpoint 1 ";

/// FNV-1a over the record's text: catches a torn or edited line.
std::uint64_t checksum(std::string_view text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

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
  // Written whole under a temporary name, then renamed: a kill never leaves a half header.
  const std::string temporary = path_ + ".tmp";
  errno = 0;
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (!f) throw IoError("cannot create checkpoint '" + temporary + "': " + std::strerror(errno));
  std::string text = magic + parameters + "\n";
  for (const auto& [index, values] : records) text += format_record(index, values);
  bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0 &&
                 ::fdatasync(::fileno(f)) == 0;
  const int cause = errno;
  written = std::fclose(f) == 0 && written;
  if (!written || std::rename(temporary.c_str(), path_.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw IoError("cannot write checkpoint '" + path_ + "': " + std::strerror(cause ? cause : errno));
  }
  file_ = std::fopen(path_.c_str(), "ab");
  if (!file_) throw IoError("cannot append to checkpoint '" + path_ + "': " + std::strerror(errno));
}

CheckpointLog::~CheckpointLog() {
  if (file_) std::fclose(file_);
}

std::string CheckpointLog::rank_path(const std::string& base, int rank) {
  return rank == 0 ? base : base + ".rank" + std::to_string(rank);
}

namespace {

std::vector<std::string> family(const std::string& base) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  if (fs::exists(base)) files.push_back(base);
  fs::path folder = fs::path(base).parent_path();
  if (folder.empty()) folder = ".";
  const std::string prefix = fs::path(base).filename().string() + ".rank";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
        name.find_first_not_of("0123456789", prefix.size()) == std::string::npos)
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

CheckpointRecords CheckpointLog::load(const std::string& base, const std::string& parameters) {
  const auto files = family(base);
  if (files.empty()) throw InvalidInput("resume", ": no checkpoint '" + base + "' to resume from");
  CheckpointRecords all;
  for (const std::string& path : files) {
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
    if (header != parameters)
      throw InvalidInput("resume", ": checkpoint '" + path +
                                       "' was made with different parameters: " + first_difference(header, parameters));
    all.merge(records);
  }
  return all;
}

bool CheckpointLog::exists(const std::string& base) { return !family(base).empty(); }

void CheckpointLog::remove_all(const std::string& base) {
  for (const std::string& path : family(base)) std::filesystem::remove(path);
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
