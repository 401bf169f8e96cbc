#pragma once
// The files a run reads and writes, so that an output that would destroy one of them is refused
// before the run does any work: an output may not be a file the run reads (by its path, or the
// same file through a link or another spelling such as ./x), lie inside a directory the run reads
// (an AMReX plotfile), or be another output of the same run. An output that is a directory, or
// whose directory does not exist, is refused at the same time instead of after the work.

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace amrstream {

// For a program (the command line): SIGINT, SIGTERM and SIGHUP remove the temporary files of the
// outputs being written before the process ends as the signal would end it, so an interrupted
// write leaves neither a partial output nor a temporary (the previous output, if any, stays).
void removeTemporariesOnSignals();

// Throws InputError naming the path unless it names an existing regular file (symbolic links
// followed): a directory, FIFO, socket or device is refused by name before anything opens it.
void checkRegularFile(const std::filesystem::path& path);

// Throws InputError naming `option` unless `path`'s extension (any case) is one of `extensions`
// (".vtp"): an output's name says what it holds, so "x.jpg" is refused where a PNG is written.
// `format` names what is written ("a PNG image").
void requireOutputExtension(const std::string& option, const std::filesystem::path& path,
                            const std::vector<std::string>& extensions, const std::string& format);

class RunFiles {
 public:
  // A file or directory the run reads. Paths that do not exist are skipped: their readers say so.
  void addInput(const std::filesystem::path& path);
  void addInputs(const std::vector<std::filesystem::path>& paths);

  // Throws InputError naming `option` and both paths when `path` cannot be written without
  // destroying an input or an output added before; otherwise records it as an output.
  void addOutput(const std::string& option, const std::filesystem::path& path);
  // The same check, without recording `path` (for files named one at a time as the run goes).
  void checkOutput(const std::string& option, const std::filesystem::path& path) const;

 private:
  struct Identity {
    dev_t device;
    ino_t inode;
    bool operator==(const Identity&) const = default;
  };
  struct File {
    std::string name;                  // the input's path, or the output's option
    std::filesystem::path path;        // as given
    std::filesystem::path canonical;   // absolute, links in its existing part resolved
    std::optional<Identity> identity;  // when it exists
    bool directory = false;
  };
  static File describe(std::string name, const std::filesystem::path& path);
  static std::optional<Identity> identityOf(const std::filesystem::path& path, bool* directory);

  std::vector<File> inputs_, outputs_;
};

}  // namespace amrstream
