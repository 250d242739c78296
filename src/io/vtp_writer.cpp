// VTP frame writer: appended raw binary data, zlib compression, 64-bit headers.
#include "io/vtp_writer.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>
#include <vtkTypeUInt8Array.h>
#include <vtkXMLPolyDataWriter.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "core/errors.hpp"
#include "io/csv_writer.hpp"  // temporary_path
#include "io/output_fields.hpp"

namespace arksph {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw OutputError("cannot write " + path + ": " + reason);
}

// A field pointer the frame must provide (only when there are particles to read).
template <class T>
const T* need(const T* p, const Frame& f, const char* what) {
  if (!p && f.n > 0) throw std::invalid_argument(std::string("write_vtp: frame has no '") + what + "' array");
  return p;
}

// A VTK array named `name` with n tuples of `comps` components.
template <class A>
vtkSmartPointer<A> make_array(const char* name, int comps, vtkIdType n) {
  auto a = vtkSmartPointer<A>::New();
  a->SetName(name);
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(n);
  return a;
}

// Builds the point-data array of one table entry from the frame.
vtkSmartPointer<vtkDataArray> field_array(const OutputField& fd, const Frame& f) {
  const auto n = static_cast<vtkIdType>(f.n);
  switch (fd.field) {
    case FieldId::velocity: {
      auto a = make_array<vtkDoubleArray>(fd.name, 3, n);
      const double* u = need(f.u, f, "u");
      const double* v = f.dimension >= 2 ? need(f.v, f, "v") : nullptr;
      for (vtkIdType i = 0; i < n; ++i) {
        const double vel[3] = {u[i], v ? v[i] : 0.0, 0.0};
        a->SetTypedTuple(i, vel);
      }
      return a;
    }
    case FieldId::pressure:
    case FieldId::density:
    case FieldId::summation_density:
    case FieldId::mass: {
      const double* src = fd.field == FieldId::pressure            ? need(f.pressure, f, "pressure")
                          : fd.field == FieldId::density           ? need(f.density, f, "density")
                          : fd.field == FieldId::summation_density ? need(f.summation_density, f, "summation_density")
                                                                   : need(f.mass, f, "mass");
      auto a = make_array<vtkDoubleArray>(fd.name, 1, n);
      if (n > 0) std::memcpy(a->GetPointer(0), src, f.n * sizeof(double));
      return a;
    }
    case FieldId::id: {
      auto a = make_array<vtkTypeInt64Array>(fd.name, 1, n);
      const std::int64_t* id = need(f.id, f, "id");
      for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, id[i]);
      return a;
    }
    case FieldId::phase: {
      auto a = make_array<vtkTypeInt32Array>(fd.name, 1, n);
      const std::int32_t* ph = need(f.phase, f, "phase");
      for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, ph[i]);
      return a;
    }
    case FieldId::smoothing_length: {
      auto a = make_array<vtkDoubleArray>(fd.name, 1, n);
      for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, f.smoothing_length);
      return a;
    }
    case FieldId::kind: {
      auto a = make_array<vtkTypeInt32Array>(fd.name, 1, n);
      for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, f.kind ? f.kind[i] : static_cast<std::int32_t>(ParticleKind::fluid));
      return a;
    }
    case FieldId::free_surface: {
      auto a = make_array<vtkTypeUInt8Array>(fd.name, 1, n);
      const std::uint8_t* s = need(f.free_surface, f, "free_surface");
      for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, s[i]);
      return a;
    }
  }
  throw std::logic_error("write_vtp: unhandled output field");
}

// Points (x, y, 0) in double precision and one vertex cell per particle.
vtkSmartPointer<vtkPolyData> make_polydata(const Frame& f) {
  const auto n = static_cast<vtkIdType>(f.n);
  const double* x = need(f.x, f, "x");
  const double* y = f.dimension >= 2 ? need(f.y, f, "y") : nullptr;
  auto xyz = make_array<vtkDoubleArray>("Points", 3, n);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const double p[3] = {x[i], y ? y[i] : 0.0, 0.0};
    xyz->SetTypedTuple(i, p);
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(n, n);
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);

  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetVerts(verts);
  for (const OutputField& fd : kOutputFields) pd->GetPointData()->AddArray(field_array(fd, f));
  for (const OutputField& fd : kOptionalOutputFields)
    if (carries(fd, f)) pd->GetPointData()->AddArray(field_array(fd, f));
  return pd;
}

// Keeps the first VTK error message of the writer (instead of printing it to stderr).
void capture_error(vtkObject*, unsigned long, void* client, void* call) {
  auto& kept = *static_cast<std::string*>(client);
  if (!kept.empty() || !call) return;
  std::string msg = static_cast<const char*>(call);
  // "ERROR: In file, line N\nvtkClass (0x..): text\n\n" -> "text"
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
  if (auto nl = msg.rfind('\n'); nl != std::string::npos) msg.erase(0, nl + 1);
  if (auto p = msg.find("): "); p != std::string::npos) msg.erase(0, p + 3);
  kept = msg.empty() ? "VTK error" : msg;
}

// The one-line reason of a failed Write(): VTK stores either an errno or one of its own codes.
std::string failure_reason(unsigned long code, const std::string& vtk_error) {
  if (code > 0 && code < vtkErrorCode::FirstVTKErrorCode) return std::strerror(static_cast<int>(code));
  if (code == vtkErrorCode::OutOfDiskSpaceError) return "no space left on device";
  if (!vtk_error.empty()) return vtk_error;
  return "VTK writer error " + std::to_string(code);
}

}  // namespace

bool carries(const OutputField& field, const Frame& f) {
  return field.field == FieldId::free_surface && f.free_surface;
}

void write_vtp(const std::string& path, const Frame& f) {
  vtkSmartPointer<vtkPolyData> pd = make_polydata(f);
  const std::string tmp = temporary_path(path);

  // Open the temporary once ourselves: a missing or read-only directory gives a clear errno reason.
  if (std::FILE* probe = std::fopen(tmp.c_str(), "wb")) {
    std::fclose(probe);
  } else {
    fail(path, std::strerror(errno));
  }

  vtkNew<vtkXMLPolyDataWriter> w;
  // Route VTK's error messages (writer and its pipeline executive) to us instead of stderr.
  std::string vtk_error, executive_error;
  vtkNew<vtkCallbackCommand> on_error, on_executive_error;
  on_error->SetCallback(capture_error);
  on_error->SetClientData(&vtk_error);
  on_executive_error->SetCallback(capture_error);
  on_executive_error->SetClientData(&executive_error);
  w->AddObserver(vtkCommand::ErrorEvent, on_error);
  w->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, on_executive_error);

  w->SetFileName(tmp.c_str());
  w->SetInputData(pd);
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  w->SetCompressorTypeToZLib();
  w->SetCompressionLevel(5);
  w->SetHeaderTypeToUInt64();
  const int ok = w->Write();
  const unsigned long code = w->GetErrorCode();
  if (!ok || code != vtkErrorCode::NoError || !vtk_error.empty()) {
    std::remove(tmp.c_str());
    fail(path, failure_reason(code, vtk_error));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    fail(path, std::strerror(err));
  }
}

}  // namespace arksph
