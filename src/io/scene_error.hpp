#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace rise {

// A scene file that cannot be used, reported the way compilers report source
// errors so that editors can jump to it: "FILE:LINE:COLUMN: MESSAGE" (1-based
// line and column), or "FILE: MESSAGE" for a problem with the file as a whole.
class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, int line, int column, std::string message)
      : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                           message),
        file_(std::move(file)),
        line_(line),
        column_(column),
        message_(std::move(message)) {}

  SceneError(std::string file, std::string message)
      : std::runtime_error(file + ": " + message),
        file_(std::move(file)),
        message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }      // 0 when the error is about the whole file
  int column() const { return column_; }  // 0 when the error is about the whole file
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_ = 0;
  int column_ = 0;
  std::string message_;
};

}  // namespace rise
