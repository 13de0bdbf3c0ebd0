// One writer per output: a second lock on the same prefix is refused naming the holder;
// a lock left by a killed process does not block; the file goes when the lock is released.
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "granular/error.hpp"
#include "granular/io/output_lock.hpp"
#include "scratch.hpp"

namespace granular {
namespace {

std::string lock_scratch(const std::string& name) { return testing::scratch_path("output_lock_test", name); }

TEST(OutputLock, ASecondWriterIsRefusedNamingTheFirst) {
  const std::string prefix = lock_scratch("run");
  {
    OutputLock first(prefix, "spreading --output run");
    EXPECT_TRUE(std::filesystem::exists(prefix + ".lock"));
    // flock locks belong to the open file description: a second open in this process conflicts too.
    try {
      OutputLock second(prefix);
      ADD_FAILURE() << "second lock on the same prefix was granted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), "output");
      const std::string what = e.what();
      EXPECT_NE(what.find("process " + std::to_string(::getpid())), std::string::npos) << what;
      EXPECT_NE(what.find("spreading --output run"), std::string::npos) << what;
    }
    OutputLock other(lock_scratch("other"));  // another prefix is independent
  }
  EXPECT_FALSE(std::filesystem::exists(prefix + ".lock"));
  OutputLock again(prefix);  // released: free again
}

TEST(OutputLock, AStaleLockOfAKilledProcessDoesNotBlock) {
  const std::string prefix = lock_scratch("killed");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputLock held(prefix, "child");
    char c = 1;
    if (::write(ready[1], &c, 1) != 1) _exit(1);
    ::pause();  // killed by the parent while holding the lock
    _exit(0);
  }
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);
  EXPECT_THROW(OutputLock{prefix}, InvalidInput);  // held by the live child
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(std::filesystem::exists(prefix + ".lock"));  // left behind by the kill
  OutputLock resumed(prefix);                              // but the lock died with its process
  ::close(ready[0]);
  ::close(ready[1]);
}

}  // namespace
}  // namespace granular
