/// \file
/// Error: what an algorithm's result holds in place of an answer. Empty when the work succeeded, a one-line
/// message when it failed, or a cancellation when the caller's progress callback returned false.
/// Cancellation is a state of its own, never a text to compare: filters/MedialProgress maps it to VTK's
/// AbortExecute, and the `medial` command maps that to its exit code (cli/CommandLine.h).
#pragma once

#include <ostream>
#include <string>
#include <utility>

namespace medial {

/// A result's error: none, a failure with a one-line message, or a cancellation (see the file).
class Error {
 public:
  Error() = default;
  /// A failure with `message` (no error when the message is empty).
  Error(std::string message)  // NOLINT(google-explicit-constructor): result.error = "..." reads best
      : kind_(message.empty() ? Kind::None : Kind::Failed), message_(std::move(message)) {}
  /// A failure with `message` (no error when it is empty).
  Error(const char* message) : Error(std::string(message)) {}  // NOLINT(google-explicit-constructor)
  /// The work stopped because the caller asked it to.
  static Error cancelled() {
    Error e;
    e.kind_ = Kind::Cancelled;
    e.message_ = "cancelled";
    return e;
  }

  /// True when there is no error.
  bool empty() const { return kind_ == Kind::None; }
  /// True when the work was cancelled.
  bool isCancelled() const { return kind_ == Kind::Cancelled; }
  /// The failure's message ("cancelled" for a cancellation, "" for none).
  const std::string& message() const { return message_; }
  /// A failure with "context: " before its message; a cancellation (or no error) as it is.
  Error within(const std::string& context) const {
    return kind_ == Kind::Failed ? Error(context + ": " + message_) : *this;
  }

  /// Writes the message.
  friend std::ostream& operator<<(std::ostream& out, const Error& e) { return out << e.message_; }
  /// The text followed by the message.
  friend std::string operator+(const std::string& text, const Error& e) { return text + e.message_; }

 private:
  enum class Kind { None, Failed, Cancelled };
  Kind kind_ = Kind::None;
  std::string message_;
};

}  // namespace medial
