#include "io/core/gdal_util.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>

#include <mutex>

namespace roofsweep::gdal {

void EnsureRegistered() {
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

ErrorCapture::ErrorCapture() {
  CPLPushErrorHandlerEx(
      [](CPLErr cls, CPLErrorNum no, const char* msg) {
        Handler(static_cast<int>(cls), static_cast<int>(no), msg);
      },
      this);
}

ErrorCapture::~ErrorCapture() { CPLPopErrorHandler(); }

void ErrorCapture::Handler(int err_class, int /*err_no*/, const char* msg) {
  auto* self = static_cast<ErrorCapture*>(CPLGetErrorHandlerUserData());
  if (!self) return;
  std::string text = msg ? msg : "";
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  if (err_class == CE_Failure || err_class == CE_Fatal) {
    self->failures_.push_back(text);
  } else if (err_class == CE_Warning) {
    self->warnings_.push_back(text);
  }
}

std::string ErrorCapture::Message(const std::string& fallback) const {
  if (!failures_.empty()) return failures_.front();
  if (!warnings_.empty()) return warnings_.back();
  return fallback;
}

ScopedThreadConfig::ScopedThreadConfig(const char* key, const char* value) : key_(key) {
  const char* old = CPLGetThreadLocalConfigOption(key, nullptr);
  if (old) {
    had_old_ = true;
    old_ = old;
  }
  CPLSetThreadLocalConfigOption(key, value);
}

ScopedThreadConfig::~ScopedThreadConfig() {
  CPLSetThreadLocalConfigOption(key_.c_str(), had_old_ ? old_.c_str() : nullptr);
}

}  // namespace roofsweep::gdal
