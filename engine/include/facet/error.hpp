#pragma once
// Errors as values: every loader returns a Result carrying either its product or an Error that
// names the file and line, so callers (CLI, viewer) decide what to do without exceptions.

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace facet {

/// A place in an input file; line 0 means "the file as a whole".
struct FileLoc {
    std::string file;
    int line = 0;
};

/// A user-facing error: where it happened and what was expected.
struct Error {
    FileLoc loc;
    std::string message;
    /// The load was stopped through its LoadControl, not by anything in the file.
    bool cancelled = false;

    /// "file:line: message" (or "file: message" for line 0), the form compilers use.
    std::string what() const {
        std::string s;
        s.reserve(loc.file.size() + message.size() + 16);
        s.append(loc.file);
        if (loc.line > 0) s.append(":").append(std::to_string(loc.line));
        if (!s.empty()) s.append(": ");
        s.append(message);
        return s;
    }
};

/// Either a value or an Error; check ok() before value().
template <class T>
class Result {
  public:
    Result(T value) : v_(std::move(value)) {}
    Result(Error error) : v_(std::move(error)) {}

    /// True when a value is held.
    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    /// The value; calling it on an error is a programmer error.
    T& value() & {
        assert(ok());
        return std::get<0>(v_);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(v_);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(v_));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    /// The error; calling it on a value is a programmer error.
    const Error& error() const {
        assert(!ok());
        return std::get<1>(v_);
    }

  private:
    std::variant<T, Error> v_;
};

/// Outcome of an operation with no product: success (the default) or an Error. Its truth value
/// means success, as Result's does: `if (Status s = f(); !s) report(s.error());`.
class Status {
  public:
    /// Success.
    Status() = default;
    /// Failure with `error`.
    Status(Error error) : error_(std::move(error)) {}

    /// True on success.
    bool ok() const { return !error_.has_value(); }
    /// True on success.
    explicit operator bool() const { return ok(); }

    /// The error; calling it on success is a programmer error.
    const Error& error() const {
        assert(!ok());
        return *error_;
    }

  private:
    std::optional<Error> error_;
};

}  // namespace facet
