// HDF5 checkpoint writer and reader (HDF5 1.10 C API; layout in io/checkpoint_layout.md).
#include "io/checkpoint.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"
#include "core/memory_limit.hpp"
#include "io/csv_writer.hpp"  // temporary_path

namespace arksph {

namespace {

constexpr const char* kFormatName = "arksph checkpoint";

// The innermost message of HDF5's error stack (read right after the failing call).
std::string hdf5_reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* out) -> herr_t {
        if (n == 0 && e && e->desc) *static_cast<std::string*>(out) = e->desc;
        return 0;
      },
      &reason);
  return reason.empty() ? "HDF5 error" : reason;
}

// Turns off HDF5's automatic error printing for the lifetime of the object (errors become
// exceptions with one-line messages instead of stacks on stderr).
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// An hid_t that closes itself. `what` names the failing call in messages.
class Hid {
 public:
  Hid(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error(what + ": " + hdf5_reason());
  }
  ~Hid() {
    if (id_ >= 0) close_(id_);
  }
  Hid(const Hid&) = delete;
  Hid& operator=(const Hid&) = delete;
  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }
  // Closes now and reports a failure (a file's close is where buffered data reaches the disk).
  void close(const std::string& what) {
    const herr_t status = close_(id_);
    id_ = -1;
    if (status < 0) throw std::runtime_error(what + ": " + hdf5_reason());
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error(what + ": " + hdf5_reason());
}

// ---- writing ----

void write_scalar(hid_t obj, const char* name, hid_t file_type, hid_t mem_type, const void* value) {
  Hid space(H5Screate(H5S_SCALAR), H5Sclose, "H5Screate");
  Hid attr(H5Acreate2(obj, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
           std::string("attribute ") + name);
  check(H5Awrite(attr, mem_type, value), std::string("attribute ") + name);
}

void write_double(hid_t obj, const char* name, double v) {
  write_scalar(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v);
}

void write_int64(hid_t obj, const char* name, long v) {
  const std::int64_t w = v;
  write_scalar(obj, name, H5T_STD_I64LE, H5T_NATIVE_INT64, &w);
}

void write_int32(hid_t obj, const char* name, int v) {
  const std::int32_t w = v;
  write_scalar(obj, name, H5T_STD_I32LE, H5T_NATIVE_INT32, &w);
}

// A variable-length UTF-8 string attribute (any length: the text lives in the global heap).
void write_string(hid_t obj, const char* name, const std::string& s) {
  Hid type(H5Tcopy(H5T_C_S1), H5Tclose, "H5Tcopy");
  check(H5Tset_size(type, H5T_VARIABLE), "H5Tset_size");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
  const char* text = s.c_str();
  write_scalar(obj, name, type, type, &text);
}

// A 1D dataset of n values: chunked, shuffled, deflate level 4, Fletcher-32 checksum.
void write_array(hid_t group, const char* name, hid_t file_type, hid_t mem_type, const void* data, std::size_t n) {
  const hsize_t dims[1] = {static_cast<hsize_t>(n)}, maxdims[1] = {H5S_UNLIMITED};
  const hsize_t chunk[1] = {std::clamp<hsize_t>(dims[0], 1, 65536)};
  Hid space(H5Screate_simple(1, dims, maxdims), H5Sclose, "H5Screate_simple");
  Hid dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "H5Pcreate");
  check(H5Pset_chunk(dcpl, 1, chunk), "H5Pset_chunk");
  check(H5Pset_shuffle(dcpl), "H5Pset_shuffle");
  check(H5Pset_deflate(dcpl, 4), "H5Pset_deflate");
  check(H5Pset_fletcher32(dcpl), "H5Pset_fletcher32");
  Hid dset(H5Dcreate2(group, name, file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
           std::string("dataset ") + name);
  if (n > 0) check(H5Dwrite(dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), std::string("dataset ") + name);
}

void write_doubles(hid_t group, const char* name, const double* data, std::size_t n) {
  write_array(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, n);
}

// Names of the state blocks in StateLayout order.
std::vector<std::pair<const char*, std::size_t>> state_blocks(const StateLayout& L) {
  std::vector<std::pair<const char*, std::size_t>> b;
  const char* pos[2] = {"x", "y"};
  const char* vel[2] = {"u", "v"};
  for (int k = 0; k < L.dim; ++k) b.emplace_back(pos[k], L.pos(k));
  for (int k = 0; k < L.dim; ++k) b.emplace_back(vel[k], L.vel(k));
  if (L.has_density) b.emplace_back("rho", L.rho());
  if (L.has_energy) b.emplace_back("e", L.energy());
  return b;
}

// The checkpoint as the bytes of an HDF5 file, built in memory (core driver, no backing store).
// HDF5 never touches the disk: a full disk or a file size limit shows up in write_image below,
// with HDF5's file already closed cleanly (a failed H5Fflush/H5Fclose on a real file leaves the
// library with a half-closed file that it tries to close again at exit).
std::vector<unsigned char> file_image(const Checkpoint& c) {
  const StateLayout L = c.layout();
  if (c.state.size() != L.size() || c.mass.size() != c.n || c.rho0.size() != c.n || c.id.size() != c.n ||
      c.phase.size() != c.n)
    throw std::logic_error("write_checkpoint: array sizes do not match n = " + std::to_string(c.n));
  Hid fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "H5Pcreate");
  check(H5Pset_fapl_core(fapl, 1 << 20, 0), "H5Pset_fapl_core");
  Hid file(H5Fcreate("arksph-checkpoint-image", H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose, "H5Fcreate");
  write_string(file, "format", kFormatName);
  write_int32(file, "format_version", c.format_version);
  write_int32(file, "dimension", c.dimension);
  write_int32(file, "has_density", c.has_density ? 1 : 0);
  if (c.has_energy) write_int32(file, "has_energy", 1);  // absent: no energy block
  write_int64(file, "particles", static_cast<long>(c.n));
  write_double(file, "time", c.time);
  write_int64(file, "steps", c.steps);
  write_int64(file, "rhs_evals", c.rhs_evals);
  write_int64(file, "step_attempts", c.step_attempts);
  write_int64(file, "error_test_fails", c.error_test_fails);
  write_double(file, "last_step", c.last_step);
  write_double(file, "next_step", c.next_step);
  write_int64(file, "output_frame", c.output_frame);
  write_int64(file, "checkpoint_index", c.checkpoint_index);
  write_int64(file, "wall_reflections", c.wall_reflections);
  write_double(file, "cpu_seconds", c.cpu_seconds);
  if (c.has_viscous_dissipation) write_double(file, "viscous_dissipation", c.viscous_dissipation);  // absent: no budget
  write_string(file, "scene_toml", c.scene_toml);
  if (!c.run_id.empty()) write_string(file, "run_id", c.run_id);
  {
    Hid state(H5Gcreate2(file, "state", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group state");
    for (const auto& [name, offset] : state_blocks(L)) write_doubles(state, name, c.state.data() + offset, c.n);
  }
  {
    Hid particles(H5Gcreate2(file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                  "group particles");
    write_doubles(particles, "mass", c.mass.data(), c.n);
    write_doubles(particles, "rho0", c.rho0.data(), c.n);
    write_array(particles, "id", H5T_STD_I64LE, H5T_NATIVE_INT64, c.id.data(), c.n);
    write_array(particles, "phase", H5T_STD_I32LE, H5T_NATIVE_INT32, c.phase.data(), c.n);
  }
  if (!c.steady_samples.empty()) {
    if (c.steady_columns < 2 || c.steady_samples.size() % static_cast<std::size_t>(c.steady_columns) != 0)
      throw std::logic_error("write_checkpoint: steady samples are not rows of steady_columns >= 2 values");
    Hid diagnostics(H5Gcreate2(file, "diagnostics", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                    "group diagnostics");
    write_int32(diagnostics, "steady_columns", c.steady_columns);
    write_doubles(diagnostics, "steady_samples", c.steady_samples.data(), c.steady_samples.size());
  }
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "H5Fflush");
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size <= 0) throw std::runtime_error("H5Fget_file_image: " + hdf5_reason());
  std::vector<unsigned char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file, image.data(), image.size()) != size)
    throw std::runtime_error("H5Fget_file_image: " + hdf5_reason());
  file.close("H5Fclose");
  return image;
}

// Writes the bytes to `path` and syncs them; throws OutputError("cannot write TARGET: reason").
void write_image(const std::string& path, const std::string& target, const std::vector<unsigned char>& image) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot write " + target + ": " + std::strerror(errno));
  int err = 0;
  for (std::size_t done = 0; done < image.size() && !err;) {
    const ssize_t w = ::write(fd, image.data() + done, image.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) err = w < 0 ? errno : EIO;
    else done += static_cast<std::size_t>(w);
  }
  if (!err && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && !err) err = errno;
  if (err) {
    std::remove(path.c_str());
    throw OutputError("cannot write " + target + ": " + std::strerror(err));
  }
}



// Pushes the directory entry of the renamed file to the disk (best effort), so that the rename is
// never seen pointing at data that a power loss would lose.
void sync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// ---- reading ----

bool has_attr(hid_t obj, const char* name) { return H5Aexists(obj, name) > 0; }

// The stored type must be one arksph writes for values read as `mem_type`: little-endian IEEE
// doubles; little-endian 64-bit integers for the ids, 32-bit for the phases, either for integer
// attributes (flags and counts are written in 32 or 64 bits). HDF5 would convert any numeric type on
// reading, so a flipped bit in a datatype message (outside the checksums' reach) could otherwise
// rescale every value silently.
void expect_stored_type(hid_t stored, hid_t mem_type, const std::string& label, bool attribute) {
  bool ok = false;
  const char* expected = "";
  if (H5Tequal(mem_type, H5T_NATIVE_DOUBLE) > 0) {
    ok = H5Tequal(stored, H5T_IEEE_F64LE) > 0;
    expected = "a little-endian 64-bit float";
  } else if (H5Tequal(mem_type, H5T_NATIVE_INT64) > 0) {
    ok = H5Tequal(stored, H5T_STD_I64LE) > 0 || (attribute && H5Tequal(stored, H5T_STD_I32LE) > 0);
    expected = attribute ? "a little-endian 32- or 64-bit integer" : "a little-endian 64-bit integer";
  } else {
    ok = H5Tequal(stored, H5T_STD_I32LE) > 0;
    expected = "a little-endian 32-bit integer";
  }
  if (!ok) throw std::runtime_error(label + " is not stored as " + expected + " as arksph writes it (damaged datatype)");
}

template <class T>
T read_scalar(hid_t obj, const char* name, hid_t mem_type) {
  if (!has_attr(obj, name)) throw std::runtime_error(std::string("attribute '") + name + "' missing");
  Hid attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, std::string("attribute ") + name);
  Hid space(H5Aget_space(attr), H5Sclose, std::string("attribute ") + name);
  if (H5Sget_simple_extent_npoints(space) != 1)
    throw std::runtime_error(std::string("attribute '") + name + "' is not a scalar");
  Hid stored(H5Aget_type(attr), H5Tclose, std::string("attribute ") + name);
  expect_stored_type(stored, mem_type, std::string("attribute '") + name + "'", true);
  T v{};
  check(H5Aread(attr, mem_type, &v), std::string("attribute ") + name);
  return v;
}

double read_double(hid_t obj, const char* name) { return read_scalar<double>(obj, name, H5T_NATIVE_DOUBLE); }
long read_int64(hid_t obj, const char* name) {
  return static_cast<long>(read_scalar<std::int64_t>(obj, name, H5T_NATIVE_INT64));
}

// A string attribute, variable-length or fixed-length.
std::string read_string(hid_t obj, const char* name) {
  if (!has_attr(obj, name)) throw std::runtime_error(std::string("attribute '") + name + "' missing");
  Hid attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, std::string("attribute ") + name);
  Hid ftype(H5Aget_type(attr), H5Tclose, std::string("attribute ") + name);
  if (H5Tget_class(ftype) != H5T_STRING) throw std::runtime_error(std::string("attribute '") + name + "' is not a string");
  Hid mtype(H5Tcopy(H5T_C_S1), H5Tclose, "H5Tcopy");
  check(H5Tset_cset(mtype, H5Tget_cset(ftype)), "H5Tset_cset");  // HDF5 converts no ASCII <-> UTF-8
  if (H5Tis_variable_str(ftype) > 0) {
    check(H5Tset_size(mtype, H5T_VARIABLE), "H5Tset_size");
    char* text = nullptr;
    check(H5Aread(attr, mtype, &text), std::string("attribute ") + name);
    std::string s = text ? text : "";
    H5free_memory(text);
    return s;
  }
  const std::size_t size = H5Tget_size(ftype);
  const MemoryLimit limit = memory_limit();
  if (static_cast<double>(size) > limit.bytes)
    throw std::runtime_error(std::string("attribute '") + name + "' of " + format_bytes(static_cast<double>(size)) +
                             " exceeds the memory limit of " + format_bytes(limit.bytes) + " (" + limit.source + ")");
  check(H5Tset_size(mtype, size + 1), "H5Tset_size");
  std::string buf(size + 1, '\0');
  check(H5Aread(attr, mtype, buf.data()), std::string("attribute ") + name);
  return std::string(buf.c_str());
}

// Reads the 1D dataset `name` of exactly n values into data (mem_type converts).
void read_array(hid_t group, const std::string& where, const char* name, hid_t mem_type, void* data, std::size_t n) {
  const std::string label = where + "/" + name;
  if (H5Lexists(group, name, H5P_DEFAULT) <= 0) throw std::runtime_error("dataset " + label + " missing");
  Hid dset(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose, "dataset " + label);
  Hid space(H5Dget_space(dset), H5Sclose, "dataset " + label);
  hsize_t dims[1] = {0};
  if (H5Sget_simple_extent_ndims(space) != 1) throw std::runtime_error("dataset " + label + " is not one-dimensional");
  H5Sget_simple_extent_dims(space, dims, nullptr);
  if (dims[0] != n)
    throw std::runtime_error("dataset " + label + " has " + std::to_string(dims[0]) + " values, expected " +
                             std::to_string(n));
  Hid stored(H5Dget_type(dset), H5Tclose, "dataset " + label);
  expect_stored_type(stored, mem_type, "dataset " + label, false);
  if (n > 0) check(H5Dread(dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "dataset " + label);
}

// The optional /diagnostics group: the steady-state samples, rows of steady_columns values.
void read_steady_samples(hid_t file, Checkpoint& c) {
  Hid diagnostics(H5Gopen2(file, "diagnostics", H5P_DEFAULT), H5Gclose, "group /diagnostics");
  const long columns = read_int64(diagnostics, "steady_columns");
  if (columns < 2 || columns > 100000) throw std::runtime_error("steady_columns = " + std::to_string(columns));
  const char* name = "steady_samples";
  if (H5Lexists(diagnostics, name, H5P_DEFAULT) <= 0) throw std::runtime_error("dataset /diagnostics/steady_samples missing");
  Hid dset(H5Dopen2(diagnostics, name, H5P_DEFAULT), H5Dclose, "dataset /diagnostics/steady_samples");
  Hid space(H5Dget_space(dset), H5Sclose, "dataset /diagnostics/steady_samples");
  hsize_t dims[1] = {0};
  if (H5Sget_simple_extent_ndims(space) != 1)
    throw std::runtime_error("dataset /diagnostics/steady_samples is not one-dimensional");
  H5Sget_simple_extent_dims(space, dims, nullptr);
  if (dims[0] % static_cast<hsize_t>(columns) != 0 || dims[0] > (hsize_t{1} << 28))
    throw std::runtime_error("dataset /diagnostics/steady_samples has " + std::to_string(dims[0]) +
                             " values, not rows of " + std::to_string(columns));
  c.steady_columns = static_cast<int>(columns);
  c.steady_samples.resize(dims[0]);
  read_array(diagnostics, "/diagnostics", name, H5T_NATIVE_DOUBLE, c.steady_samples.data(), c.steady_samples.size());
}

Checkpoint read_file(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("no such file");
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("not a regular file");
  if (H5Fis_hdf5(path.c_str()) <= 0) throw std::runtime_error("not an HDF5 file (or truncated)");
  Hid file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "H5Fopen");
  if (!has_attr(file, "format") || read_string(file, "format") != kFormatName)
    throw std::runtime_error("not an arksph checkpoint (attribute format != \"" + std::string(kFormatName) + "\")");
  Checkpoint c;
  c.format_version = static_cast<int>(read_int64(file, "format_version"));
  if (c.format_version != kCheckpointFormatVersion)
    throw std::runtime_error("format_version " + std::to_string(c.format_version) + ", this arksph reads version " +
                             std::to_string(kCheckpointFormatVersion));
  c.dimension = static_cast<int>(read_int64(file, "dimension"));
  if (c.dimension != 1 && c.dimension != 2)
    throw std::runtime_error("dimension " + std::to_string(c.dimension) + " is not 1 or 2");
  c.has_density = read_int64(file, "has_density") != 0;
  c.has_energy = has_attr(file, "has_energy") && read_int64(file, "has_energy") != 0;
  const long n = read_int64(file, "particles");
  if (n <= 0) throw std::runtime_error("particles = " + std::to_string(n));
  c.n = static_cast<std::size_t>(n);
  // The arrays below take n values each: a count no memory holds is refused before allocating.
  const double bytes = static_cast<double>(n) * (8.0 * (2 * c.dimension + 2 + 2) + 8 + 4);
  const MemoryLimit limit = memory_limit();
  if (bytes > limit.bytes)
    throw std::runtime_error("particles = " + std::to_string(n) + " needs " + format_bytes(bytes) +
                             ", more than the memory limit of " + format_bytes(limit.bytes) + " (" + limit.source + ")");
  c.time = read_double(file, "time");
  c.steps = read_int64(file, "steps");
  c.rhs_evals = read_int64(file, "rhs_evals");
  c.step_attempts = read_int64(file, "step_attempts");
  c.error_test_fails = read_int64(file, "error_test_fails");
  c.last_step = read_double(file, "last_step");
  c.next_step = read_double(file, "next_step");
  c.output_frame = read_int64(file, "output_frame");
  c.checkpoint_index = read_int64(file, "checkpoint_index");
  c.wall_reflections = read_int64(file, "wall_reflections");
  c.cpu_seconds = has_attr(file, "cpu_seconds") ? read_double(file, "cpu_seconds") : 0.0;
  c.has_viscous_dissipation = has_attr(file, "viscous_dissipation");
  if (c.has_viscous_dissipation) c.viscous_dissipation = read_double(file, "viscous_dissipation");
  c.scene_toml = read_string(file, "scene_toml");
  if (has_attr(file, "run_id")) c.run_id = read_string(file, "run_id");

  const StateLayout L = c.layout();
  c.state.assign(L.size(), 0.0);
  {
    if (H5Lexists(file, "state", H5P_DEFAULT) <= 0) throw std::runtime_error("group /state missing");
    Hid state(H5Gopen2(file, "state", H5P_DEFAULT), H5Gclose, "group /state");
    for (const auto& [name, offset] : state_blocks(L))
      read_array(state, "/state", name, H5T_NATIVE_DOUBLE, c.state.data() + offset, c.n);
  }
  {
    if (H5Lexists(file, "particles", H5P_DEFAULT) <= 0) throw std::runtime_error("group /particles missing");
    Hid particles(H5Gopen2(file, "particles", H5P_DEFAULT), H5Gclose, "group /particles");
    c.mass.resize(c.n);
    c.rho0.resize(c.n);
    c.id.resize(c.n);
    c.phase.resize(c.n);
    read_array(particles, "/particles", "mass", H5T_NATIVE_DOUBLE, c.mass.data(), c.n);
    read_array(particles, "/particles", "rho0", H5T_NATIVE_DOUBLE, c.rho0.data(), c.n);
    read_array(particles, "/particles", "id", H5T_NATIVE_INT64, c.id.data(), c.n);
    read_array(particles, "/particles", "phase", H5T_NATIVE_INT32, c.phase.data(), c.n);
  }
  if (H5Lexists(file, "diagnostics", H5P_DEFAULT) > 0) read_steady_samples(file, c);
  file.close("H5Fclose");
  return c;
}

}  // namespace

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  std::vector<unsigned char> image;
  try {
    QuietHdf5 quiet;
    image = file_image(c);
  } catch (const std::logic_error&) {
    throw;
  } catch (const std::exception& e) {  // HDF5 failed in memory: not a disk problem
    throw std::runtime_error("cannot write " + path + ": " + echo_value(e.what()));
  }
  const std::string tmp = temporary_path(path);
  write_image(tmp, path, image);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    throw OutputError("cannot write " + path + ": rename: " + std::strerror(err));
  }
  const std::string dir = std::filesystem::path(path).parent_path().string();
  sync_directory(dir.empty() ? "." : dir);
}

Checkpoint read_checkpoint(const std::string& path) {
  try {
    QuietHdf5 quiet;
    return read_file(path);
  } catch (const std::bad_alloc&) {
    throw OutOfMemory("an allocation failed while reading checkpoint " + path);
  } catch (const std::exception& e) {
    throw InputError(path + ": cannot read checkpoint: " + e.what());
  }
}

}  // namespace arksph
