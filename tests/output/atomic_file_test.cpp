// AtomicFile and FileSetWriter where the output's place is unusual: a file being replaced keeps
// its permissions, a symbolic link at the output stays and the file it names is written, a loop
// of links and a name at the file-name limit are handled, a signal removes the temporaries, and
// two writers of one set never mix their files.

#include "output/atomic_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "formats/file_set_writer.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::output {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public testing::TempDirTest {
 protected:
  void write(const fs::path& target, const std::string& text) {
    AtomicFile file(target);
    file.write(std::as_bytes(std::span(text.data(), text.size())));
    file.commit();
  }
  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  static unsigned mode(const fs::path& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 ? info.st_mode & 07777 : 0;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> all;
    for (const auto& entry : fs::directory_iterator(dir_)) all.push_back(entry.path().filename());
    return all;
  }
};

TEST_F(AtomicFileTest, AReplacedFileKeepsItsPermissions) {
  for (const unsigned kept : {0400u, 0600u, 0640u}) {
    const fs::path target = dir_ / "out.vtp";
    write(target, "old");
    ASSERT_EQ(::chmod(target.c_str(), kept), 0);
    write(target, "new");
    EXPECT_EQ(read(target), "new");
    EXPECT_EQ(mode(target), kept) << std::oct << kept;
    fs::remove(target);
  }
}

TEST_F(AtomicFileTest, WritesThroughASymbolicLinkWhichStays) {
  fs::create_directories(dir_ / "real");
  fs::create_symlink("real/target.vtp", dir_ / "link.vtp");  // names a file not there yet
  fs::create_symlink("link.vtp", dir_ / "second.vtp");       // a link to the link
  write(dir_ / "second.vtp", "first");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.vtp"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "second.vtp"));
  EXPECT_EQ(read(dir_ / "real" / "target.vtp"), "first");
  write(dir_ / "link.vtp", "second");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.vtp"));
  EXPECT_EQ(read(dir_ / "real" / "target.vtp"), "second");
}

TEST_F(AtomicFileTest, ALoopOfLinksFailsNamingTheOutput) {
  fs::create_symlink("b.vtp", dir_ / "a.vtp");
  fs::create_symlink("a.vtp", dir_ / "b.vtp");
  try {
    write(dir_ / "a.vtp", "x");
    FAIL() << "a loop of links was written";
  } catch (const std::system_error& e) {
    EXPECT_NE(std::string(e.what()).find("a.vtp"), std::string::npos) << e.what();
    EXPECT_EQ(e.code(), std::errc::too_many_symbolic_link_levels);
  }
  EXPECT_TRUE(fs::is_symlink(dir_ / "a.vtp"));
  EXPECT_EQ(names().size(), 2u);  // no temporary left
}

TEST_F(AtomicFileTest, ANameAtTheFileNameLimitIsWritten) {
  const long limit = ::pathconf(dir_.c_str(), _PC_NAME_MAX);
  ASSERT_GT(limit, 8);
  const fs::path target = dir_ / (std::string(std::size_t(limit) - 4, 'a') + ".vtp");
  write(target, "long");
  EXPECT_EQ(read(target), "long");
  EXPECT_EQ(names().size(), 1u);
}

// The child writes, installs the handlers and is ended by SIGTERM mid-write.
TEST_F(AtomicFileTest, ASignalRemovesTheTemporaries) {
  const fs::path target = dir_ / "out.vtp";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    removeTemporariesOnSignals();
    AtomicFile first(target), second(dir_ / "other.vtp");
    const std::string text = "partial";
    first.write(std::as_bytes(std::span(text.data(), text.size())));
    std::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_TRUE(names().empty()) << names().front();
}

// While another writer holds the directory's lock, a set's commit waits: its files appear
// together after the other's, never between them.
TEST_F(AtomicFileTest, ASetCommitsItsFilesWhileNoOtherSetDoes) {
  const int held = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(::flock(held, LOCK_EX), 0);
  std::thread writer([&] {
    formats::FileSetWriter set;
    const std::string text = "set";
    for (const char* name : {"d.cells", "d.exa"})
      set.add(dir_ / name, std::as_bytes(std::span(text.data(), text.size())));
    set.commit();
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_FALSE(fs::exists(dir_ / "d.cells"));  // waiting for the lock
  EXPECT_FALSE(fs::exists(dir_ / "d.exa"));
  ::close(held);
  writer.join();
  EXPECT_EQ(read(dir_ / "d.cells"), "set");
  EXPECT_EQ(read(dir_ / "d.exa"), "set");
}

}  // namespace
}  // namespace amrstream::output
