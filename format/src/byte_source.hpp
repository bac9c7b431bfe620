// Internal: random-access byte sources for the reader (a file, or a copy of a memory buffer).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace spt::detail {

class ByteSource {
public:
    virtual ~ByteSource() = default;
    virtual uint64_t size() const = 0;
    // Reads exactly n bytes at off; false when they are not all there or the read fails.
    virtual bool read(uint64_t off, size_t n, uint8_t* dst) = 0;
};

class MemorySource final : public ByteSource {
public:
    MemorySource(const uint8_t* p, size_t n) : data_(p, p + n) {}
    uint64_t size() const override { return data_.size(); }
    bool read(uint64_t off, size_t n, uint8_t* dst) override {
        if (off > data_.size() || n > data_.size() - off) return false;
        if (n) std::memcpy(dst, data_.data() + off, n);
        return true;
    }
private:
    std::vector<uint8_t> data_;
};

class FileSource final : public ByteSource {
public:
    static std::unique_ptr<FileSource> open(const std::string& path) {
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (!f) return nullptr;
        if (fseeko(f, 0, SEEK_END) != 0) { std::fclose(f); return nullptr; }
        const off_t end = ftello(f);
        if (end < 0) { std::fclose(f); return nullptr; }
        return std::unique_ptr<FileSource>(new FileSource(f, uint64_t(end)));
    }
    ~FileSource() override { std::fclose(f_); }
    uint64_t size() const override { return size_; }
    bool read(uint64_t off, size_t n, uint8_t* dst) override {
        if (off > size_ || n > size_ - off) return false;
        if (n == 0) return true;
        if (fseeko(f_, off_t(off), SEEK_SET) != 0) return false;
        return std::fread(dst, 1, n, f_) == n;
    }
private:
    FileSource(std::FILE* f, uint64_t size) : f_(f), size_(size) {}
    std::FILE* f_;
    uint64_t size_;
};

}  // namespace spt::detail
