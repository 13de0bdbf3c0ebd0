// libFuzzer target: checkpoint files read on --resume. Corrupt records are skipped, a foreign
// file is InvalidInput; nothing crashes.
#include <cstdint>
#include <string>

#include "granular/ensemble/checkpoint_log.hpp"
#include "granular/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    std::string header;
    granular::CheckpointLog::parse_records(text, &header);
  } catch (const granular::InvalidInput&) {
  }
  return 0;
}
