// Output writers: VTP round trip through VTK's reader, PVD collection, CSV, JSON, and I/O failures.
#include <doctest/doctest.h>
#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkVariant.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "test_support.hpp"
#include "core/errors.hpp"
#include "io/csv_writer.hpp"
#include "io/output_fields.hpp"
#include "io/frame_order.hpp"
#include "io/pvd_writer.hpp"
#include "io/pvtp_writer.hpp"
#include "io/summary_json.hpp"
#include "io/vtp_writer.hpp"

namespace fs = std::filesystem;
using namespace arksph;
using arksph::testing::ScratchDir;
using arksph::testing::slurp;

namespace {



bool has_tmp_file(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  return false;
}

// Particle fields with distinct, non-round values (ids beyond the 32-bit range, negative phases).
struct Particles {
  std::size_t n;
  std::vector<double> x, y, u, v, p, rho, rho_sum, m;
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> phase, kind;
  std::vector<std::uint8_t> surface;
  double h = 0.0123456789;
  explicit Particles(std::size_t n_) : n(n_) {
    for (std::size_t i = 0; i < n; ++i) {
      const double k = static_cast<double>(i);
      x.push_back(0.1 * k + 1.0 / 3.0);
      y.push_back(std::sqrt(k + 2.0));
      u.push_back(std::sin(k));
      v.push_back(std::cos(k) * 1e-7);
      p.push_back(std::exp(0.3 * k) - 7.0);
      rho.push_back(1000.0 + 1.0 / (k + 1.0));
      rho_sum.push_back(999.0 - 1.0 / (k + 3.0));
      m.push_back(1e-3 * (k + 0.5) / 3.0);
      id.push_back(1'000'000'000'000LL + 7 * static_cast<std::int64_t>(i));
      phase.push_back(static_cast<std::int32_t>(i % 3) - 1);
      kind.push_back(static_cast<std::int32_t>(i % 2));
      surface.push_back(static_cast<std::uint8_t>(i % 5 == 1));
    }
  }
  Frame frame(int dimension) const {
    Frame f;
    f.dimension = dimension;
    f.n = n;
    f.time = 0.25;
    f.x = x.data(), f.y = dimension >= 2 ? y.data() : nullptr;
    f.u = u.data(), f.v = dimension >= 2 ? v.data() : nullptr;
    f.pressure = p.data(), f.density = rho.data(), f.summation_density = rho_sum.data(), f.mass = m.data();
    f.id = id.data(), f.phase = phase.data();
    f.smoothing_length = h, f.kind = kind.data();
    return f;
  }
};

vtkSmartPointer<vtkPolyData> read_vtp(const std::string& path) {
  vtkNew<vtkXMLPolyDataReader> r;
  r->SetFileName(path.c_str());
  r->Update();
  return r->GetOutput();
}

// The exact value a table entry should hold for particle i, component c.
double expected(const Particles& P, FieldId field, int dim, std::size_t i, int c) {
  switch (field) {
    case FieldId::velocity: return c == 0 ? P.u[i] : (c == 1 && dim >= 2 ? P.v[i] : 0.0);
    case FieldId::pressure: return P.p[i];
    case FieldId::density: return P.rho[i];
    case FieldId::summation_density: return P.rho_sum[i];
    case FieldId::mass: return P.m[i];
    case FieldId::id: return static_cast<double>(P.id[i]);
    case FieldId::phase: return P.phase[i];
    case FieldId::smoothing_length: return P.h;
    case FieldId::kind: return P.kind[i];
    case FieldId::free_surface: return P.surface[i];
  }
  return NAN;
}

void check_vtp_round_trip(int dim) {
  ScratchDir tmp("vtp" + std::to_string(dim));
  const Particles P(50);
  const std::string path = tmp / "particles_000000.vtp";
  write_vtp(path, P.frame(dim));
  CHECK_FALSE(has_tmp_file(tmp.dir));

  // Binary appended raw data, zlib compressed, 64-bit headers, integral id/phase types.
  const std::string text = slurp(path);
  CHECK(text.find("compressor=\"vtkZLibDataCompressor\"") != std::string::npos);
  CHECK(text.find("header_type=\"UInt64\"") != std::string::npos);
  CHECK(text.find("<AppendedData encoding=\"raw\">") != std::string::npos);
  CHECK(text.find("type=\"Int64\" Name=\"id\"") != std::string::npos);
  CHECK(text.find("type=\"Int32\" Name=\"phase\"") != std::string::npos);

  auto pd = read_vtp(path);
  REQUIRE(pd);
  REQUIRE(pd->GetNumberOfPoints() == 50);
  CHECK(pd->GetNumberOfVerts() == 50);
  CHECK(pd->GetNumberOfCells() == 50);
  for (vtkIdType i = 0; i < 50; ++i) {
    double q[3];
    pd->GetPoint(i, q);
    CHECK(q[0] == P.x[i]);
    CHECK(q[1] == (dim >= 2 ? P.y[i] : 0.0));
    CHECK(q[2] == 0.0);
  }
  CHECK(pd->GetPointData()->GetNumberOfArrays() == static_cast<int>(kOutputFields.size()));
  for (const OutputField& fd : kOutputFields) {
    CAPTURE(fd.name);
    vtkDataArray* a = pd->GetPointData()->GetArray(fd.name);
    REQUIRE(a != nullptr);
    CHECK(a->GetNumberOfComponents() == fd.components);
    CHECK(a->GetNumberOfTuples() == 50);
    switch (fd.type) {
      case FieldType::Float64: CHECK(a->GetDataType() == VTK_DOUBLE); break;
      case FieldType::Int64: CHECK((a->GetDataType() == VTK_LONG || a->GetDataType() == VTK_LONG_LONG)); break;
      case FieldType::Int32: CHECK(a->GetDataType() == VTK_INT); break;
    }
    CHECK(a->GetDataTypeSize() == (fd.type == FieldType::Int32 ? 4 : 8));
    int bad = 0;
    for (vtkIdType i = 0; i < 50; ++i)
      for (int c = 0; c < fd.components; ++c) {
        if (fd.type == FieldType::Int64) {  // compare as integers: no double rounding
          if (a->GetVariantValue(i).ToTypeInt64() != P.id[i]) ++bad;
        } else if (a->GetComponent(i, c) != expected(P, fd.field, dim, i, c)) {
          ++bad;
        }
      }
    CHECK(bad == 0);
  }
}

}  // namespace

TEST_CASE("output: the field table lists the documented point-data arrays and renders as markdown") {
  std::vector<std::string> names;
  for (const auto& f : kOutputFields) names.emplace_back(f.name);
  CHECK(names == std::vector<std::string>{"velocity", "pressure", "density", "summation_density", "mass", "id", "phase",
                                          "h", "kind"});
  const std::string md = output_fields_markdown();
  CHECK(md.rfind("| name | components | type | unit | description |\n|---|---|---|---|---|\n", 0) == 0);
  CHECK(md.find("| `velocity` | 3 | Float64 | m/s |") != std::string::npos);
  CHECK(md.find("| `id` | 1 | Int64 |") != std::string::npos);
  CHECK(md.find("| `free_surface` | 1 | UInt8 | - |") != std::string::npos);
  CHECK(std::count(md.begin(), md.end(), '\n') ==
        2 + static_cast<long>(kOutputFields.size() + kOptionalOutputFields.size()));
}

TEST_CASE("output: the free_surface array is written exactly when the frame carries it") {
  ScratchDir tmp("vtpsurface");
  const Particles P(20);
  Frame f = P.frame(2);
  write_vtp(tmp / "plain.vtp", f);
  CHECK(read_vtp(tmp / "plain.vtp")->GetPointData()->GetArray("free_surface") == nullptr);
  f.free_surface = P.surface.data();
  write_vtp(tmp / "surface.vtp", f);
  auto pd = read_vtp(tmp / "surface.vtp");
  CHECK(pd->GetPointData()->GetNumberOfArrays() == static_cast<int>(kOutputFields.size()) + 1);
  vtkDataArray* a = pd->GetPointData()->GetArray("free_surface");
  REQUIRE(a != nullptr);
  CHECK(a->GetDataType() == VTK_UNSIGNED_CHAR);
  int bad = 0;
  for (vtkIdType i = 0; i < 20; ++i) bad += a->GetComponent(i, 0) != expected(P, FieldId::free_surface, 2, i, 0);
  CHECK(bad == 0);
  // The same frame, rows shuffled: written in id order with the array permuted alike.
  std::vector<std::size_t> order(20);
  for (std::size_t k = 0; k < 20; ++k) order[k] = (7 * k + 3) % 20;
  Particles Q(20);
  for (std::size_t k = 0; k < 20; ++k) {
    Q.id[k] = P.id[order[k]];
    Q.surface[k] = P.surface[order[k]];
  }
  Frame g = Q.frame(2);
  g.free_surface = Q.surface.data();
  write_vtp(tmp / "shuffled.vtp", FrameInIdOrder(g).frame());
  auto shuffled = read_vtp(tmp / "shuffled.vtp");
  vtkDataArray* b = shuffled->GetPointData()->GetArray("free_surface");
  REQUIRE(b != nullptr);
  bad = 0;
  for (vtkIdType i = 0; i < 20; ++i) bad += b->GetComponent(i, 0) != P.surface[static_cast<std::size_t>(i)];
  CHECK(bad == 0);
  // The index of pieces declares the array with the pieces that carry it.
  write_pvtp(tmp / "plain.pvtp", {"a.vtp"});
  write_pvtp(tmp / "surface.pvtp", {"a.vtp"}, true);
  CHECK(slurp(tmp / "plain.pvtp").find("free_surface") == std::string::npos);
  CHECK(slurp(tmp / "surface.pvtp").find("<PDataArray type=\"UInt8\" Name=\"free_surface\"") != std::string::npos);
}

TEST_CASE("output: VTP round trip through vtkXMLPolyDataReader is exact (2D)") { check_vtp_round_trip(2); }

TEST_CASE("output: VTP in 1D has y = 0 and velocity (u, 0, 0)") { check_vtp_round_trip(1); }

TEST_CASE("output: VTP rejects a frame that lacks a field, and writes an empty frame") {
  ScratchDir tmp("vtpbad");
  const Particles P(5);
  Frame f = P.frame(2);
  f.pressure = nullptr;
  CHECK_THROWS_AS(write_vtp(tmp / "a.vtp", f), std::invalid_argument);
  CHECK_FALSE(fs::exists(tmp / "a.vtp"));

  Frame empty;
  write_vtp(tmp / "empty.vtp", empty);
  auto pd = read_vtp(tmp / "empty.vtp");
  CHECK(pd->GetNumberOfPoints() == 0);
  CHECK(pd->GetPointData()->GetArray("velocity") != nullptr);
}

TEST_CASE("output: PVD collection after three adds") {
  ScratchDir tmp("pvd");
  PvdCollection pvd(tmp.dir.string());
  const double times[3] = {0.0, 0.1, 1.0 / 3.0};
  const std::string files[3] = {"particles_000000.vtp", "particles_000001.vtp", "particles_000002.vtp"};
  for (int k = 0; k < 3; ++k) pvd.add(times[k], files[k]);
  CHECK(pvd.path() == tmp / "particles.pvd");
  CHECK_FALSE(has_tmp_file(tmp.dir));

  // Exactly three DataSet lines.
  const std::string text = slurp(pvd.path());
  std::size_t count = 0;
  for (auto pos = text.find("<DataSet "); pos != std::string::npos; pos = text.find("<DataSet ", pos + 1)) ++count;
  CHECK(count == 3);

  // A real XML parse: VTKFile/Collection/DataSet, times read back exactly.
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.path().c_str());
  REQUIRE(parser->Parse() == 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  REQUIRE(root);
  CHECK(std::string(root->GetName()) == "VTKFile");
  CHECK(std::string(root->GetAttribute("type")) == "Collection");
  vtkXMLDataElement* coll = root->FindNestedElementWithName("Collection");
  REQUIRE(coll);
  REQUIRE(coll->GetNumberOfNestedElements() == 3);
  for (int k = 0; k < 3; ++k) {
    vtkXMLDataElement* ds = coll->GetNestedElement(k);
    CHECK(std::string(ds->GetName()) == "DataSet");
    CHECK(std::strtod(ds->GetAttribute("timestep"), nullptr) == times[k]);
    CHECK(std::string(ds->GetAttribute("file")) == files[k]);
  }
}

TEST_CASE("output: CSV time series rows are flushed, small tables") {
  ScratchDir tmp("csv");
  const std::string path = tmp / "timeseries.csv";
  TimeseriesCsv csv;
  csv.open(path, {"t", "dt", "kinetic_energy"});
  csv.row({0.0, 0.1, 1.0 / 3.0});
  csv.row({0.5, 2.5e-4, 1e30});
  // Read while still open: the rows must already be on disk.
  CHECK(slurp(path) == "t,dt,kinetic_energy\n0,0.1,0.3333333333\n0.5,0.00025,1e+30\n");
  CHECK_THROWS_AS(csv.row({1.0}), std::invalid_argument);
  csv.close();

  write_csv(tmp / "table.csv", {"x", "u,err"}, {{1, 2}, {0.125, -3}});
  CHECK(slurp(tmp / "table.csv") == "x,\"u,err\"\n1,2\n0.125,-3\n");
  CHECK_FALSE(has_tmp_file(tmp.dir));
}

TEST_CASE("output: JSON escaping, number formatting and order") {
  CHECK(json_quote("a \"q\" \\ b\nc\td\x01") == R"("a \"q\" \\ b\nc\td\u0001")");
  // Well-formed UTF-8 passes through; bytes that are not (a stray continuation byte, a lone lead
  // byte, an overlong form, a surrogate) become \ufffd, so the file stays valid JSON.
  CHECK(json_quote("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80") == "\"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80\"");
  CHECK(json_quote("a\xFF" "b\x80" "c\xC3") == R"("a\ufffdb\ufffdc\ufffd")");
  CHECK(json_quote("\xC0\xAF \xED\xA0\x80") == R"("\ufffd\ufffd \ufffd\ufffd\ufffd")");
  CHECK(json_number(std::nan("")) == "null");
  CHECK(json_number(INFINITY) == "null");
  CHECK(json_number(-INFINITY) == "null");
  for (double x : {0.1, 1.0 / 3.0, 30.0, -0.0, 1e-300, 5e-324, DBL_MAX, 123456789012345678.0, -2.5e-7}) {
    const std::string s = json_number(x);
    CAPTURE(s);
    CHECK(std::strtod(s.c_str(), nullptr) == x);
    CHECK(std::signbit(std::strtod(s.c_str(), nullptr)) == std::signbit(x));
  }

  Json j = Json::object();
  j.set("scene", "cav\"ity").set("particles", 2500).set("final_time", 30.0).set("ok", true);
  j.set("bad", std::nan("")).set("none", nullptr);
  j["metrics"].set("cv", 0.01).set("big", std::int64_t{9007199254740993});
  j.set("terms", std::vector<std::string>{"viscosity:morris", "walls:ghost"});
  j.set("empty_obj", Json::object()).set("empty_arr", Json::array());
  j.set("particles", 2501);  // replacing keeps the position
  CHECK(j.dump(0) ==
        R"({"scene":"cav\"ity","particles":2501,"final_time":30,"ok":true,"bad":null,"none":null,)"
        R"("metrics":{"cv":0.01,"big":9007199254740993},"terms":["viscosity:morris","walls:ghost"],)"
        R"("empty_obj":{},"empty_arr":[]})");

  Json small = Json::object().set("a", 1).set("b", Json::array().push(true)).set("c", Json::object());
  CHECK(small.dump() == "{\n  \"a\": 1,\n  \"b\": [\n    true\n  ],\n  \"c\": {}\n}");
  CHECK_THROWS_AS(Json(1.0).push(2), std::logic_error);

  ScratchDir tmp("json");
  write_json_atomic(tmp / "summary.json", j);
  CHECK(slurp(tmp / "summary.json") == j.dump() + "\n");
  CHECK_FALSE(has_tmp_file(tmp.dir));
}

TEST_CASE("output: writing into a missing or unusable directory throws and leaves no file") {
  ScratchDir tmp("fail");
  std::ofstream(tmp / "plainfile") << "x";  // a file where a directory is expected
  std::vector<std::string> dirs = {tmp / "missing", tmp / "plainfile"};
  if (::geteuid() != 0) {  // root ignores permissions
    fs::create_directory(tmp / "readonly");
    fs::permissions(tmp / "readonly", fs::perms::owner_read | fs::perms::owner_exec);
    dirs.push_back(tmp / "readonly");
  }
  const Particles P(3);
  for (const std::string& d : dirs) {
    CAPTURE(d);
    auto expect_fail = [&](const std::string& path, auto&& write) {
      CAPTURE(path);
      bool thrown = false;
      try {
        write(path);
      } catch (const std::runtime_error& e) {
        thrown = true;
        const std::string msg = e.what();
        CAPTURE(msg);
        CHECK(msg.rfind("cannot write " + path + ": ", 0) == 0);
        CHECK(msg.find('\n') == std::string::npos);
      }
      CHECK(thrown);
      CHECK_FALSE(fs::exists(path));
      CHECK_FALSE(fs::exists(temporary_path(path)));
    };
    const std::string dd = d + "/";
    expect_fail(dd + "f.vtp", [&](const std::string& p) { write_vtp(p, P.frame(2)); });
    expect_fail(dd + "particles.pvd", [&](const std::string&) { PvdCollection(d).add(0.0, "f.vtp"); });
    expect_fail(dd + "summary.json", [&](const std::string& p) { write_json_atomic(p, Json::object()); });
    expect_fail(dd + "timeseries.csv", [&](const std::string& p) { TimeseriesCsv().open(p, {"t"}); });
    expect_fail(dd + "table.csv", [&](const std::string& p) { write_csv(p, {"t"}, {{1.0}}); });
  }
  CHECK_FALSE(fs::exists(tmp / "missing"));
}

TEST_CASE("output: a full disk during the write throws and removes the temporary") {
  if (!fs::exists("/dev/full")) return;
  ScratchDir tmp("full");
  const Particles P(20);
  // The temporary is a symlink to /dev/full: opening works, every write fails with ENOSPC.
  auto expect_enospc = [&](const std::string& path, auto&& write) {
    CAPTURE(path);
    fs::create_symlink("/dev/full", temporary_path(path));
    CHECK_THROWS_WITH_AS(write(path), ("cannot write " + path + ": No space left on device").c_str(),
                         OutputError);
    CHECK_FALSE(fs::exists(path));
    CHECK_FALSE(fs::is_symlink(temporary_path(path)));
  };
  expect_enospc(tmp / "f.vtp", [&](const std::string& p) { write_vtp(p, P.frame(2)); });
  expect_enospc(tmp / "s.json", [&](const std::string& p) { write_json_atomic(p, Json::object()); });
  CHECK_THROWS_WITH_AS(TimeseriesCsv("/dev/full", {"t"}), "cannot write /dev/full: No space left on device",
                       std::runtime_error);
}
