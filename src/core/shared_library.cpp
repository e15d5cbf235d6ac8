#include "core/shared_library.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace rise {
namespace {

std::string lastError() {
  const char* error = dlerror();
  return error != nullptr ? error : "no reason given";
}

}  // namespace

SharedLibrary::SharedLibrary(std::string name)
    : name_(std::move(name)), handle_(dlopen(name_.c_str(), RTLD_NOW | RTLD_LOCAL)) {
  if (handle_ == nullptr) throw std::runtime_error("cannot load " + name_ + ": " + lastError());
}

void* SharedLibrary::address(const char* name) const {
  dlerror();
  void* const address = dlsym(handle_, name);
  if (address == nullptr)
    throw std::runtime_error(name_ + " has no function " + name + ": " + lastError());
  return address;
}

}  // namespace rise
