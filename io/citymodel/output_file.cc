#include "io/citymodel/output_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace fs = std::filesystem;

void CheckOutputPath(const std::string& path, bool overwrite) {
  const fs::path p(path);
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw Error(AtLine(path, 0, "output folder '" + dir.string() + "' does not exist"));
  if (fs::exists(p, ec) && !overwrite)
    throw Error(AtLine(path, 0, "output exists; pass overwrite (-overwrite) to replace it"));
  if (fs::is_directory(p, ec)) throw Error(AtLine(path, 0, "output is a folder"));
}

void CheckInputFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(AtLine(path, 0, "no such file"));
  if (!fs::is_regular_file(path, ec)) throw Error(AtLine(path, 0, "not a regular file"));
}

OutputFile::OutputFile(const std::string& path, bool overwrite) : path_(path) {
  CheckOutputPath(path, overwrite);
  static std::atomic<int> counter{0};
  const fs::path p(path);
  const std::string ext = p.extension().string();
  temp_ = (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(getpid()) +
                              "-" + std::to_string(counter++) + ext))
              .string();
}

OutputFile::~OutputFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void WriteTextFile(const std::string& path, const std::string& text, bool overwrite) {
  OutputFile out(path, overwrite);
  {
    std::ofstream f(out.temp_path());
    f << text;
    if (!f) throw Error(path + ": cannot write");
  }
  out.Commit();
}

void OutputFile::Commit() {
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw Error(AtLine(
        path_, 0, std::string("cannot rename temporary file into place: ") + std::strerror(errno)));
  committed_ = true;
}

}  // namespace roofsweep
