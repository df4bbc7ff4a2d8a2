// HDF5 (C API) checkpoint files: one group per array kind, one dataset per named array.
#include "solver/io/Checkpoint.h"

#include <hdf5.h>

#include "solver/core/Checksum.h"
#include "solver/core/InputError.h"
#include "solver/io/SafeFile.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace lbdem::io {

namespace {

constexpr const char* kRealGroup = "/reals";
constexpr const char* kIntegerGroup = "/integers";
constexpr const char* kCaseAttribute = "case_toml";
constexpr const char* kChecksumAttribute = "checksum";
constexpr const char* kRunIdAttribute = "run_id";
constexpr const char* kCaseHashAttribute = "case_hash";
// 2: a checksum of the case and every array; 3: the run's id and case hash, in the checksum too
// (older formats are still read: 1 only with --force, as it has no checksum).
constexpr int kFormatVersion = 3;
// Arrays that may hold NaN legitimately: the metrics of the last output (undefined metrics).
constexpr const char* kMayBeNonFinite = "run/last_metric/";

/// Owns one HDF5 identifier and closes it with the matching function.
class Handle {
public:
    Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : m_id(id), m_close(close) {
        if (id < 0) throw std::runtime_error(what);
    }
    ~Handle() { m_close(m_id); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    hid_t get() const { return m_id; }

private:
    hid_t m_id;
    herr_t (*m_close)(hid_t);
};

void writeStringAttribute(hid_t object, const char* name, const std::string& value) {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create a string type");
    H5Tset_size(type.get(), value.size() + 1);
    Handle space(H5Screate(H5S_SCALAR), H5Sclose, "cannot create a dataspace");
    Handle attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                     H5Aclose, std::string("cannot create attribute ") + name);
    if (H5Awrite(attribute.get(), type.get(), value.c_str()) < 0)
        throw std::runtime_error(std::string("cannot write attribute ") + name);
}

std::string readStringAttribute(hid_t object, const char* name) {
    Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose,
                     std::string("missing attribute ") + name);
    Handle type(H5Aget_type(attribute.get()), H5Tclose, "bad attribute type");
    std::string value(H5Tget_size(type.get()), '\0');
    if (H5Aread(attribute.get(), type.get(), value.data()) < 0)
        throw std::runtime_error(std::string("cannot read attribute ") + name);
    value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
    return value;
}

template <class T>
void writeDataset(hid_t group, const std::string& name, const std::vector<T>& values, hid_t type) {
    const hsize_t size = values.size();
    Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose, "cannot create a dataspace");
    Handle dataset(
        H5Dcreate2(group, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose, "cannot create dataset " + name);
    if (size > 0 && H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw std::runtime_error("cannot write dataset " + name);
}

template <class T> std::vector<T> readDataset(hid_t group, const std::string& name, hid_t type) {
    Handle dataset(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "missing dataset " + name);
    Handle space(H5Dget_space(dataset.get()), H5Sclose, "bad dataspace of " + name);
    hsize_t size = 0;
    H5Sget_simple_extent_dims(space.get(), &size, nullptr);
    std::vector<T> values(size);
    if (size > 0 && H5Dread(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw std::runtime_error("cannot read dataset " + name);
    return values;
}

/// Names of the links in a group, in creation-independent (name) order.
std::vector<std::string> linkNames(hid_t group) {
    std::vector<std::string> names;
    H5Literate(
        group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
        [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t {
            static_cast<std::vector<std::string>*>(data)->emplace_back(name);
            return 0;
        },
        &names);
    return names;
}

/// Datasets are stored flat, '/' in array names replaced, so that names need no subgroups.
std::string encodeName(std::string name) {
    for (char& c : name)
        if (c == '/') c = '|';
    return name;
}

std::string decodeName(std::string name) {
    for (char& c : name)
        if (c == '|') c = '/';
    return name;
}

using solver::Checksum;

/// The checksum of a checkpoint's case and arrays, in name order.
std::string checksumOf(const CheckpointData& data) {
    Checksum sum;
    sum.add(data.case_toml);
    // The run's identity counts only when present, so that format-2 files still verify.
    if (!data.run_id.empty() || !data.case_hash.empty()) {
        sum.add(data.run_id);
        sum.add(data.case_hash);
    }
    for (const auto& [name, values] : data.state.reals) {
        sum.add(name);
        sum.add(values.data(), values.size() * sizeof(double));
    }
    for (const auto& [name, values] : data.state.integers) {
        sum.add(name);
        sum.add(values.data(), values.size() * sizeof(std::int64_t));
    }
    return sum.hex();
}

/// Refuse a checkpoint whose arrays fail the checksum or hold a value that is not finite.
void verify(const std::string& path, const CheckpointData& data,
            const std::string& storedChecksum) {
    if (!storedChecksum.empty() && storedChecksum != checksumOf(data))
        throw solver::InputError(
            path + " is damaged: its case and arrays do not match the checksum written with "
                   "them; resume from a copy, or start the run again with lbdem run --force");
    for (const auto& [name, values] : data.state.reals) {
        if (name.rfind(kMayBeNonFinite, 0) == 0) continue;
        for (const double value : values)
            if (!std::isfinite(value))
                throw solver::InputError(path + " is damaged: array '" + name +
                                         "' holds a value that is not finite");
    }
}

/// Write the case, its identity, the checksum and every array of data into the open HDF5 file.
void writeContent(hid_t file, const CheckpointData& data) {
    writeStringAttribute(file, kCaseAttribute, data.case_toml);
    writeStringAttribute(file, "format", "lbdem checkpoint " + std::to_string(kFormatVersion));
    writeStringAttribute(file, kChecksumAttribute, checksumOf(data));
    writeStringAttribute(file, kRunIdAttribute, data.run_id);
    writeStringAttribute(file, kCaseHashAttribute, data.case_hash);
    Handle reals(H5Gcreate2(file, kRealGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                 "cannot create group");
    for (const auto& [name, values] : data.state.reals)
        writeDataset(reals.get(), encodeName(name), values, H5T_NATIVE_DOUBLE);
    Handle integers(H5Gcreate2(file, kIntegerGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    H5Gclose, "cannot create group");
    for (const auto& [name, values] : data.state.integers)
        writeDataset(integers.get(), encodeName(name), values, H5T_NATIVE_INT64);
}

/// The checkpoint as the bytes of an HDF5 file, built in memory (HDF5's core driver without a
/// backing store): HDF5 never writes to the disk, since HDF5 1.10 crashes at exit after a file
/// whose close failed (a full disk); the caller writes the bytes with its own error handling.
std::string fileImage(const CheckpointData& data) {
    std::size_t bytes = data.case_toml.size();
    for (const auto& [name, values] : data.state.reals)
        bytes += values.size() * sizeof(double) + name.size();
    for (const auto& [name, values] : data.state.integers)
        bytes += values.size() * sizeof(std::int64_t) + name.size();
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a property list");
    // One allocation of about the final size: the arrays and room for HDF5's metadata.
    if (H5Pset_fapl_core(access.get(), bytes + (bytes >> 4) + (std::size_t(1) << 16), false) < 0)
        throw std::runtime_error("cannot select HDF5's in-memory driver");
    Handle file(H5Fcreate("checkpoint.h5", H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), H5Fclose,
                "cannot create the checkpoint in memory");
    writeContent(file.get(), data);
    // Without a flush the image's superblock still gives the end of the empty file.
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0)
        throw std::runtime_error("cannot flush the checkpoint in memory");
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    std::string image(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
    if (size <= 0 || H5Fget_file_image(file.get(), image.data(), image.size()) != size)
        throw std::runtime_error("cannot take the image of the checkpoint");
    return image;
}

/// The string attribute called name, or "" when the file has none.
std::string optionalAttribute(hid_t file, const char* name) {
    return H5Aexists(file, name) > 0 ? readStringAttribute(file, name) : std::string();
}

CheckpointData readFile(const std::string& path, bool acceptUnverified) {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "not an HDF5 file");
    CheckpointData data;
    data.case_toml = readStringAttribute(file.get(), kCaseAttribute);
    data.run_id = optionalAttribute(file.get(), kRunIdAttribute);
    data.case_hash = optionalAttribute(file.get(), kCaseHashAttribute);
    Handle reals(H5Gopen2(file.get(), kRealGroup, H5P_DEFAULT), H5Gclose, "missing group /reals");
    for (const auto& name : linkNames(reals.get()))
        data.state.reals[decodeName(name)] =
            readDataset<double>(reals.get(), name, H5T_NATIVE_DOUBLE);
    Handle integers(H5Gopen2(file.get(), kIntegerGroup, H5P_DEFAULT), H5Gclose,
                    "missing group /integers");
    for (const auto& name : linkNames(integers.get()))
        data.state.integers[decodeName(name)] =
            readDataset<std::int64_t>(integers.get(), name, H5T_NATIVE_INT64);
    const std::string checksum = optionalAttribute(file.get(), kChecksumAttribute);
    // Without its checksum nothing tells damaged arrays from sound ones: a checksum that is
    // missing (or whose name was damaged) must not switch the verification off silently.
    if (checksum.empty() && !acceptUnverified)
        throw solver::InputError(path + " carries no checksum (attribute '" + kChecksumAttribute +
                                 "'), so it cannot be verified; lbdem resume --force resumes it "
                                 "unverified");
    data.verified = !checksum.empty();
    verify(path, data, checksum);
    return data;
}

} // namespace

void writeCheckpoint(const std::string& path, const CheckpointData& data) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors become one sentence, not an HDF5 trace
    std::string image;
    try {
        image = fileImage(data);
    } catch (const std::exception& error) {
        throw std::runtime_error("cannot write the checkpoint " + path + ": " + error.what());
    }
    // Durable: the previous checkpoint is replaced only by one that is on the disk. On failure
    // (a full disk) the temporary file is removed and the previous checkpoint stays.
    const bool previous = std::filesystem::exists(path);
    try {
        replaceFile(path, image, true);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(error.what() + std::string(previous ? "; the previous checkpoint "
                                                                       "is left as it was"
                                                                     : ""));
    }
}

CheckpointData readCheckpoint(const std::string& path, bool acceptUnverified) {
    if (!std::filesystem::exists(path)) throw solver::InputError(path + " does not exist");
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors become exceptions with our messages
    try {
        return readFile(path, acceptUnverified);
    } catch (const solver::InputError&) {
        throw;
    } catch (const std::exception& error) {
        throw solver::InputError(path + " is not a readable lbdem checkpoint (" + error.what() +
                                 ")");
    }
}

} // namespace lbdem::io
