#include "granular/study/resumed_checkpoint.hpp"

#include <algorithm>

#include "granular/ensemble/checkpoint_log.hpp"

namespace granular {

nlohmann::json resumed_checkpoint(const std::vector<std::string>& checkpoints) {
  for (const std::string& c : checkpoints)
    if (const std::string made_by = CheckpointLog::code_of(c); !made_by.empty()) {
      std::vector<std::string> versions;
      for (const std::string& each : checkpoints)
        for (const std::string& code : CheckpointLog::codes_of(each))
          if (std::find(versions.begin(), versions.end(), code) == versions.end()) versions.push_back(code);
      if (std::find(versions.begin(), versions.end(), CheckpointLog::this_code()) == versions.end())
        versions.push_back(CheckpointLog::this_code());
      return {{"made_by", made_by}, {"resumed_by", CheckpointLog::this_code()}, {"versions", versions}};
    }
  return nullptr;
}

}  // namespace granular
