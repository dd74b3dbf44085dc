#include "slides/io/hdf5_file.h"

#include "slides/core/error.h"
#include "slides/io/atomic_file.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>

namespace slides {

namespace {

/// Before the first HDF5 call: no error-stack printing (failures become OutputError here), and
/// no library shutdown at exit. A file whose final flush failed (a full disk) stays half closed
/// in HDF5: closing it again, as that shutdown would, crashes the process (SIGSEGV after the
/// run's error message). Every handle is closed by its owner, so nothing needs the shutdown.
void startHdf5() {
    static const bool started = [] {
        H5dont_atexit();
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        return true;
    }();
    (void)started;
}

/// " (the system's reason)" of a failed HDF5 write whose errno was cleared before it; empty
/// when the system gave none.
std::string systemReason() {
    return errno ? std::string(" (") + std::strerror(errno) + ")" : std::string();
}

/// Rows per chunk: about 64 KiB of data, never more than the dataset.
hsize_t chunkRows(std::size_t rows, std::size_t rowBytes) {
    const std::size_t target = std::max<std::size_t>(1, 65536 / rowBytes);
    return static_cast<hsize_t>(std::min(rows, target));
}

} // namespace

Hdf5Handle& Hdf5Handle::operator=(Hdf5Handle&& other) noexcept {
    if (this != &other) {
        close();
        id_ = other.id_;
        other.id_ = H5I_INVALID_HID;
    }
    return *this;
}

bool Hdf5Handle::close() {
    if (id_ < 0) return true;
    herr_t status = -1;
    switch (H5Iget_type(id_)) {
    case H5I_FILE: status = H5Fclose(id_); break;
    case H5I_GROUP: status = H5Gclose(id_); break;
    case H5I_DATASET: status = H5Dclose(id_); break;
    case H5I_DATASPACE: status = H5Sclose(id_); break;
    case H5I_DATATYPE: status = H5Tclose(id_); break;
    case H5I_ATTR: status = H5Aclose(id_); break;
    case H5I_GENPROP_LST: status = H5Pclose(id_); break;
    default: break;
    }
    id_ = H5I_INVALID_HID; // never closed twice: a failed file close leaves HDF5's object broken
    return status >= 0;
}

Hdf5File::Hdf5File(std::filesystem::path path, Hdf5Access access)
    : path_(std::move(path)), access_(access) {
    startHdf5();
    if (access == Hdf5Access::create || access == Hdf5Access::createChecksummed) {
        checksums_ = access == Hdf5Access::createChecksummed;
        Hdf5Handle fileAccess(H5Pcreate(H5P_FILE_ACCESS));
        if (!fileAccess.valid() ||
            (checksums_ &&
             H5Pset_libver_bounds(fileAccess.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST) < 0))
            fail("cannot describe the file");
        file_ = Hdf5Handle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fileAccess.get()));
        if (!file_.valid()) fail("cannot create the file");
        return;
    }
    if (!std::filesystem::exists(path_)) fail("no such file");
    const unsigned flags = access == Hdf5Access::readOnly ? H5F_ACC_RDONLY : H5F_ACC_RDWR;
    file_ = Hdf5Handle(H5Fopen(path_.c_str(), flags, H5P_DEFAULT));
    if (!file_.valid()) fail("not a readable HDF5 file (damaged or incomplete)");
}

void Hdf5File::fail(const std::string& what) const {
    if (access_ == Hdf5Access::readOnly) throw InputError(path_.string(), 0, "", what);
    throw OutputError("cannot write " + path_.string() + ": " + what);
}

Hdf5Handle Hdf5File::createGroup(const std::string& path) const {
    Hdf5Handle group(H5Gcreate2(file_.get(), path.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (!group.valid()) fail("cannot create group " + path);
    return group;
}

void Hdf5File::writeRaw(hid_t parent, const std::string& name, hid_t type, const void* data,
                        std::size_t rows, std::size_t columns, std::string_view units) const {
    const std::array<hsize_t, 2> dims{static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)};
    const int rank = columns == 1 ? 1 : 2;
    Hdf5Handle space(H5Screate_simple(rank, dims.data(), nullptr));
    Hdf5Handle creation(H5Pcreate(H5P_DATASET_CREATE));
    if (!space.valid() || !creation.valid()) fail("cannot describe dataset " + name);
    // An empty dataset cannot be chunked (chunk extents must be ≥ 1 and ≤ the fixed size).
    if (rows > 0) {
        const std::array<hsize_t, 2> chunk{chunkRows(rows, columns * H5Tget_size(type)), dims[1]};
        if (H5Pset_chunk(creation.get(), rank, chunk.data()) < 0 ||
            H5Pset_shuffle(creation.get()) < 0 || H5Pset_deflate(creation.get(), 4) < 0 ||
            (checksums_ && H5Pset_fletcher32(creation.get()) < 0))
            fail("cannot set compression of dataset " + name);
    }
    Hdf5Handle dataset(H5Dcreate2(parent, name.c_str(), type, space.get(), H5P_DEFAULT,
                                  creation.get(), H5P_DEFAULT));
    if (!dataset.valid()) fail("cannot create dataset " + name);
    errno = 0;
    if (rows > 0 && H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail("cannot write dataset " + name + systemReason());
    writeAttribute(dataset.get(), "units", units);
}

void Hdf5File::writeDataset(hid_t parent, const std::string& name, std::span<const double> values,
                            std::size_t columns, std::string_view units) const {
    writeRaw(parent, name, H5T_NATIVE_DOUBLE, values.data(), values.size() / columns, columns,
             units);
}

void Hdf5File::writeDataset(hid_t parent, const std::string& name,
                            std::span<const std::int32_t> values, std::string_view units) const {
    writeRaw(parent, name, H5T_NATIVE_INT32, values.data(), values.size(), 1, units);
}

void Hdf5File::writeDataset(hid_t parent, const std::string& name,
                            std::span<const std::uint64_t> values, std::string_view units) const {
    writeRaw(parent, name, H5T_NATIVE_UINT64, values.data(), values.size(), 1, units);
}

void Hdf5File::writeDataset(hid_t parent, const std::string& name, std::span<const Vec3> values,
                            std::string_view units) const {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 rows are written as three doubles");
    writeRaw(parent, name, H5T_NATIVE_DOUBLE, values.data(), values.size(), 3, units);
}

void Hdf5File::writeAttribute(hid_t object, const std::string& name, std::string_view text) const {
    Hdf5Handle type(H5Tcopy(H5T_C_S1));
    Hdf5Handle space(H5Screate(H5S_SCALAR));
    if (!type.valid() || !space.valid() ||
        H5Tset_size(type.get(), std::max<std::size_t>(1, text.size())) < 0)
        fail("cannot describe attribute " + name);
    Hdf5Handle attribute(
        H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
    const std::string padded = text.empty() ? std::string(1, '\0') : std::string(text);
    if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), padded.data()) < 0)
        fail("cannot write attribute " + name);
}

namespace {

template <typename Value>
bool writeScalarAttribute(hid_t object, const std::string& name, hid_t type, Value value) {
    Hdf5Handle space(H5Screate(H5S_SCALAR));
    Hdf5Handle attribute(
        H5Acreate2(object, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT));
    return attribute.valid() && H5Awrite(attribute.get(), type, &value) >= 0;
}

} // namespace

void Hdf5File::writeAttribute(hid_t object, const std::string& name, double value) const {
    if (!writeScalarAttribute(object, name, H5T_NATIVE_DOUBLE, value))
        fail("cannot write attribute " + name);
}

void Hdf5File::writeAttribute(hid_t object, const std::string& name, std::int64_t value) const {
    if (!writeScalarAttribute(object, name, H5T_NATIVE_INT64, value))
        fail("cannot write attribute " + name);
}

bool Hdf5File::exists(const std::string& path) const {
    return H5Lexists(file_.get(), path.c_str(), H5P_DEFAULT) > 0;
}

void Hdf5File::remove(const std::string& path) const {
    if (H5Ldelete(file_.get(), path.c_str(), H5P_DEFAULT) < 0) fail("cannot remove " + path);
}

std::size_t Hdf5File::rowsOf(const std::string& path, std::size_t columns) const {
    Hdf5Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
    if (!dataset.valid()) fail("missing dataset " + path);
    Hdf5Handle space(H5Dget_space(dataset.get()));
    std::array<hsize_t, 2> dims{0, 1};
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank != (columns == 1 ? 1 : 2) ||
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0 || dims[1] != columns)
        fail("dataset " + path + " does not have " + std::to_string(columns) + " column(s)");
    // Deflate expands its input at most 1032-fold: more rows than that are a damaged
    // description, refused before they are allocated.
    const double stored = static_cast<double>(H5Dget_storage_size(dataset.get()));
    if (static_cast<double>(dims[0]) * static_cast<double>(columns) * 8 > 1032 * stored + 65536)
        fail("dataset " + path + " claims " + std::to_string(dims[0]) +
             " rows, more than its storage holds (damaged)");
    return static_cast<std::size_t>(dims[0]);
}

void Hdf5File::readRaw(const std::string& path, hid_t type, void* data, std::size_t values) const {
    if (values == 0) return;
    Hdf5Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
    if (!dataset.valid() || H5Dread(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        fail("cannot read dataset " + path + " (damaged: checksum or decompression failed)");
}

std::vector<double> Hdf5File::readDoubles(const std::string& path, std::size_t columns) const {
    const std::size_t rows = rowsOf(path, columns);
    std::vector<double> values(rows * columns);
    readRaw(path, H5T_NATIVE_DOUBLE, values.data(), values.size());
    return values;
}

std::vector<std::int32_t> Hdf5File::readInt32(const std::string& path) const {
    std::vector<std::int32_t> values(rowsOf(path, 1));
    readRaw(path, H5T_NATIVE_INT32, values.data(), values.size());
    return values;
}

std::vector<std::uint64_t> Hdf5File::readUInt64(const std::string& path) const {
    std::vector<std::uint64_t> values(rowsOf(path, 1));
    readRaw(path, H5T_NATIVE_UINT64, values.data(), values.size());
    return values;
}

void Hdf5File::readAttribute(const std::string& object, const std::string& name, hid_t type,
                             void* value) const {
    Hdf5Handle attribute(
        H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
    if (!attribute.valid() || H5Aread(attribute.get(), type, value) < 0)
        fail("missing or unreadable attribute " + name + " of " + object);
}

std::string Hdf5File::readText(const std::string& object, const std::string& name) const {
    Hdf5Handle attribute(
        H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
    if (!attribute.valid()) fail("missing attribute " + name + " of " + object);
    Hdf5Handle type(H5Aget_type(attribute.get()));
    if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0)
        fail("attribute " + name + " of " + object + " is not a fixed-length string");
    std::string text(H5Tget_size(type.get()), '\0');
    readAttribute(object, name, type.get(), text.data());
    return text.substr(0, text.find('\0'));
}

double Hdf5File::readDouble(const std::string& object, const std::string& name) const {
    double value = 0;
    readAttribute(object, name, H5T_NATIVE_DOUBLE, &value);
    return value;
}

std::int64_t Hdf5File::readInt64(const std::string& object, const std::string& name) const {
    std::int64_t value = 0;
    readAttribute(object, name, H5T_NATIVE_INT64, &value);
    return value;
}

void Hdf5File::flush() const {
    errno = 0;
    if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("cannot flush to disk" + systemReason());
}

void Hdf5File::close() {
    errno = 0;
    if (!file_.close()) fail("cannot close the file" + systemReason());
}

} // namespace slides
