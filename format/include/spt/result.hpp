// Errors are values: every fallible libspt call returns Result or Status.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace spt {

enum class Code : uint8_t {
    Ok = 0,
    IoError,         // the operating system refused a read or write
    NotSpt,          // the signature is wrong
    Unsupported,     // a newer major version, an unknown critical chunk, a reserved value
    Corrupt,         // checksum mismatch, bad length, inconsistent values
    Truncated,       // the data ends early
    LimitExceeded,   // a size or count is above the reader's limits
    InvalidArgument, // the caller passed something the format cannot hold
    BadState,        // call out of order, or after an unrecoverable error
};

const char* code_name(Code c);

struct Error {
    Code code = Code::Ok;
    std::string message;     // says what is wrong; names the byte offset where there is one
    uint64_t offset = 0;     // byte offset in the file, when known
};

// A minimal expected<T, Error>: C++20 has no std::expected.
template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : value_(std::move(value)) {}
    Result(Error e) : error_(std::move(e)) {}
    bool ok() const { return value_.has_value(); }
    explicit operator bool() const { return ok(); }
    T& value() & { return *value_; }
    const T& value() const& { return *value_; }
    T&& value() && { return std::move(*value_); }
    T& operator*() { return *value_; }
    const T& operator*() const { return *value_; }
    T* operator->() { return &*value_; }
    const T* operator->() const { return &*value_; }
    const Error& error() const { return error_; }
private:
    std::optional<T> value_;
    Error error_;
};

struct [[nodiscard]] Status {
    Status() = default;
    Status(Error e) : error_(std::move(e)) {}
    bool ok() const { return error_.code == Code::Ok; }
    explicit operator bool() const { return ok(); }
    const Error& error() const { return error_; }
private:
    Error error_;
};

inline Error make_error(Code c, std::string msg, uint64_t offset = 0) {
    return Error{c, std::move(msg), offset};
}

}  // namespace spt
