// Hdf5File: a small owner of HDF5 C-API handles and the few calls the particle output needs
// (HDF5 1.10, the library of Debian's libhdf5-dev).
//
// Every identifier is closed by its owner; every failing call throws, naming the file and the
// object, instead of HDF5's own error stack print: OutputError when writing, InputError when
// reading (a file given to the program, such as a checkpoint). Datasets are chunked,
// byte-shuffled and deflate-compressed (and Fletcher-32 checksummed on request, so corrupted
// data is refused on reading); each carries its SI unit in a `units` attribute.
#pragma once

#include "slides/core/vector.h"

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace slides {

/// Owns one HDF5 identifier (file, group, dataset, dataspace, property list, datatype,
/// attribute) and closes it with the matching H5?close.
class Hdf5Handle {
public:
    Hdf5Handle() = default;
    explicit Hdf5Handle(hid_t id) : id_(id) {}
    Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_) { other.id_ = H5I_INVALID_HID; }
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept;
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;
    ~Hdf5Handle() { close(); }

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    /// Closes now; returns false if HDF5 reported an error (e.g. a failed final flush).
    bool close();

private:
    hid_t id_ = H5I_INVALID_HID;
};

enum class Hdf5Access {
    create,
    /// Created in HDF5's latest format, whose metadata (object headers with their attributes,
    /// B-trees, heaps) carry checksums, every chunked dataset a Fletcher-32 checksum.
    createChecksummed,
    readOnly,
    readWrite
};

/// One HDF5 file: create it and add groups, datasets and attributes, or read them back.
class Hdf5File {
public:
    /// Creates (truncates) the file, or opens an existing one; throws if it cannot.
    explicit Hdf5File(std::filesystem::path path, Hdf5Access access = Hdf5Access::create);

    /// Creates the group at path (parents must exist), e.g. "/frames/000003".
    Hdf5Handle createGroup(const std::string& path) const;

    /// A dataset of rows × columns (columns = 1: one-dimensional) of doubles, int32 or uint64.
    void writeDataset(hid_t parent, const std::string& name, std::span<const double> values,
                      std::size_t columns, std::string_view units) const;
    void writeDataset(hid_t parent, const std::string& name, std::span<const std::int32_t> values,
                      std::string_view units) const;
    void writeDataset(hid_t parent, const std::string& name, std::span<const std::uint64_t> values,
                      std::string_view units) const;
    /// Vectors as rows × 3 doubles.
    void writeDataset(hid_t parent, const std::string& name, std::span<const Vec3> values,
                      std::string_view units) const;

    void writeAttribute(hid_t object, const std::string& name, std::string_view text) const;
    void writeAttribute(hid_t object, const std::string& name, double value) const;
    void writeAttribute(hid_t object, const std::string& name, std::int64_t value) const;

    bool exists(const std::string& path) const;
    /// Unlinks the object at path (e.g. a group of frames written after a checkpoint).
    void remove(const std::string& path) const;

    /// A dataset's values; columns is the length of its second dimension (1: one-dimensional).
    std::vector<double> readDoubles(const std::string& path, std::size_t columns) const;
    std::vector<std::int32_t> readInt32(const std::string& path) const;
    std::vector<std::uint64_t> readUInt64(const std::string& path) const;
    std::string readText(const std::string& object, const std::string& name) const;
    double readDouble(const std::string& object, const std::string& name) const;
    std::int64_t readInt64(const std::string& object, const std::string& name) const;

    /// Pushes everything written so far to the file on disk.
    void flush() const;
    /// Closes the file; throws OutputError if the final write fails.
    void close();

    hid_t root() const { return file_.get(); }
    const std::filesystem::path& path() const { return path_; }

private:
    void writeRaw(hid_t parent, const std::string& name, hid_t type, const void* data,
                  std::size_t rows, std::size_t columns, std::string_view units) const;
    void readRaw(const std::string& path, hid_t type, void* data, std::size_t values) const;
    std::size_t rowsOf(const std::string& path, std::size_t columns) const;
    void readAttribute(const std::string& object, const std::string& name, hid_t type,
                       void* value) const;
    [[noreturn]] void fail(const std::string& what) const;

    std::filesystem::path path_;
    Hdf5Access access_;
    bool checksums_ = false;
    Hdf5Handle file_;
};

} // namespace slides
