// HDF5 (C API) checkpoint files: one group per array kind, one dataset per named array.
#include "solver/io/Checkpoint.h"

#include <hdf5.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace lbdem::io {

namespace {

constexpr const char* kRealGroup = "/reals";
constexpr const char* kIntegerGroup = "/integers";
constexpr const char* kCaseAttribute = "case_toml";
constexpr int kFormatVersion = 1;

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
    Handle dataset(H5Dcreate2(group, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                              H5P_DEFAULT),
                   H5Dclose, "cannot create dataset " + name);
    if (size > 0 && H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw std::runtime_error("cannot write dataset " + name);
}

template <class T>
std::vector<T> readDataset(hid_t group, const std::string& name, hid_t type) {
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
    H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
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

void writeFile(const std::string& path, const CheckpointData& data) {
    Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                "cannot create " + path);
    writeStringAttribute(file.get(), kCaseAttribute, data.case_toml);
    writeStringAttribute(file.get(), "format", "lbdem checkpoint " + std::to_string(kFormatVersion));
    Handle reals(H5Gcreate2(file.get(), kRealGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Gclose, "cannot create group");
    for (const auto& [name, values] : data.state.reals)
        writeDataset(reals.get(), encodeName(name), values, H5T_NATIVE_DOUBLE);
    Handle integers(H5Gcreate2(file.get(), kIntegerGroup, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    H5Gclose, "cannot create group");
    for (const auto& [name, values] : data.state.integers)
        writeDataset(integers.get(), encodeName(name), values, H5T_NATIVE_INT64);
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error("cannot flush " + path);
}

} // namespace

void writeCheckpoint(const std::string& path, const CheckpointData& data) {
    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
    try {
        writeFile(temporary, data);
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " + error.message());
    }
}

CheckpointData readCheckpoint(const std::string& path) {
    if (!std::filesystem::exists(path)) throw std::runtime_error(path + " does not exist");
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // errors become exceptions with our messages
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                path + " is not a readable HDF5 checkpoint");
    CheckpointData data;
    data.case_toml = readStringAttribute(file.get(), kCaseAttribute);
    Handle reals(H5Gopen2(file.get(), kRealGroup, H5P_DEFAULT), H5Gclose, "missing group /reals");
    for (const auto& name : linkNames(reals.get()))
        data.state.reals[decodeName(name)] = readDataset<double>(reals.get(), name, H5T_NATIVE_DOUBLE);
    Handle integers(H5Gopen2(file.get(), kIntegerGroup, H5P_DEFAULT), H5Gclose,
                    "missing group /integers");
    for (const auto& name : linkNames(integers.get()))
        data.state.integers[decodeName(name)] =
            readDataset<std::int64_t>(integers.get(), name, H5T_NATIVE_INT64);
    return data;
}

} // namespace lbdem::io
