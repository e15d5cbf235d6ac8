// A shared library opened when a program first needs it (dlopen), not when
// the program starts: a large library linked in the usual way is mapped and
// relocated at every start, needed or not, which costs a few milliseconds of
// every command. The functions are taken from it by name.
#pragma once

#include <string>

namespace rise {

class SharedLibrary {
 public:
  // Opens the library of that file name (its soname), searched for as the
  // dynamic linker searches. Throws std::runtime_error naming it and why
  // it cannot be opened. The library stays loaded until the process ends:
  // threads it started (Embree's workers) may run its code until then.
  explicit SharedLibrary(std::string name);
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The function of that name, of type Function. Throws std::runtime_error
  // when the library has none.
  template <typename Function>
  Function* function(const char* name) const {
    return reinterpret_cast<Function*>(address(name));
  }

 private:
  void* address(const char* name) const;

  std::string name_;
  void* handle_;
};

}  // namespace rise

// A member named after a library's function `name`, declared in the library's
// header, holding that function taken from `library` (a SharedLibrary
// declared before it): a struct of these is the library's interface, loaded.
#define RISE_LIBRARY_FUNCTION(library, name) \
  decltype(&::name) name = (library).function<decltype(::name)>(#name)
