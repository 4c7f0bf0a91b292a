#pragma once

// Small GDAL helpers shared by the io/core sources (not part of the API).

#include <string>
#include <vector>

namespace roofsweep::gdal {

// GDALAllRegister, once per process.
void EnsureRegistered();

// While alive, GDAL errors and warnings raised on this thread are collected
// instead of printed, so they can become part of a roofsweep::Error message.
class ErrorCapture {
 public:
  ErrorCapture();
  ~ErrorCapture();
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;

  bool HasFailure() const { return !failures_.empty(); }
  // The first failure message (the cause; later ones tend to be follow-ups),
  // else the last warning, else `fallback`.
  std::string Message(const std::string& fallback) const;

 private:
  static void Handler(int err_class, int err_no, const char* msg);
  std::vector<std::string> failures_;
  std::vector<std::string> warnings_;
};

// Sets a GDAL configuration option for this thread only while alive.
class ScopedThreadConfig {
 public:
  ScopedThreadConfig(const char* key, const char* value);
  ~ScopedThreadConfig();
  ScopedThreadConfig(const ScopedThreadConfig&) = delete;
  ScopedThreadConfig& operator=(const ScopedThreadConfig&) = delete;

 private:
  std::string key_;
  std::string old_;
  bool had_old_ = false;
};

}  // namespace roofsweep::gdal
