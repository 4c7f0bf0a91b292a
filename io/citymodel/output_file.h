#pragma once

#include <string>

namespace roofsweep {

// A file written under a temporary name beside its destination and renamed
// into place only when complete, so a crash or an error never leaves a
// half-written output (and never clobbers an existing one).
class OutputFile {
 public:
  // Throws roofsweep::Error when the destination's folder does not exist or
  // the destination exists and `overwrite` is false. The temporary name keeps
  // the destination's extension (GDAL drivers choose their layout from it):
  // "<dir>/.<name>.tmp<pid>-<n>.<ext>".
  OutputFile(const std::string& path, bool overwrite);
  // Removes the temporary file unless Commit() succeeded.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_; }
  // Renames the temporary file onto the destination (atomic on POSIX).
  void Commit();

 private:
  std::string path_;
  std::string temp_;
  bool committed_ = false;
};

// Writes `text` to `path` under a temporary name and renames it into
// place (OutputFile): nothing half-written is left. Throws "PATH: cannot
// write" when the write fails, or as OutputFile does.
void WriteTextFile(const std::string& path, const std::string& text, bool overwrite);

// Throws when `path`'s parent folder is missing or `path` exists and
// `overwrite` is false (the message says to pass overwrite/-overwrite).
void CheckOutputPath(const std::string& path, bool overwrite);

// Throws "PATH: no such file" when `path` is not a readable regular file.
void CheckInputFile(const std::string& path);

}  // namespace roofsweep
