// Halo volume on a 100 x 100 lattice (dx = 0.01, h = 2 dx, Wendland support 2h, skin 0.15 of the
// support: cut-off c = 4.6 dx) against the band model: the particles within c of a box but outside
// it fill a band of area (perimeter' c + n_corners pi c^2 / 4), perimeter' counting only the sides
// of the box that face another box or a periodic side (a wall has nothing behind it). The lattice
// puts floor(c/dx) or ceil(c/dx) columns along a side depending on where the side falls, so the
// count may differ from the area / dx^2 by one column along the counted perimeter and by the
// discretisation of the corner discs (2 c / dx + 1 points each).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "mpi_test_support.hpp"
#include "parallel/halo.hpp"
#include "parallel/migration.hpp"

using namespace arksph::parallel;
using namespace arksph::parallel::testing;

TEST_CASE("halo volume: 100 x 100 lattice, h = 2 dx, Wendland support 2h + skin, against the band model") {
  const Communicator comm;
  const int n = 100;
  const double dx = 1.0 / n, c = 1.15 * 4.0 * dx;
  for (const bool periodic : {true, false}) {
    CAPTURE(periodic);
    const Domain dom = unit_domain(1.0, 1.0, periodic, periodic);
    ParticleFields p(2, N_FIELDS);
    for (int k = comm.rank(); k < n * n; k += comm.size()) {
      p.id.push_back(static_cast<std::uint64_t>(k));
      p.field[X].push_back((k % n + 0.5) * dx);
      p.field[Y].push_back((k / n + 0.5) * dx);
      for (int f = U; f < N_FIELDS; ++f) p.field[static_cast<std::size_t>(f)].push_back(1.0);
    }
    const Decomposition d = decompose(comm, CellGrid(dom, c), p);
    migrate(comm, d, p);
    HaloExchange exchange;
    ParticleFields halo;
    exchange.exchange(comm, d, p, c, halo);
    // The band model for this rank's box.
    const Box box = d.box(comm.rank());
    double open_perimeter = 0, perimeter = 0;
    int open_corners = 0;
    bool open_side[4];  // x lo, x hi, y lo, y hi
    for (int a = 0; a < 2; ++a)
      for (int hi = 0; hi < 2; ++hi) {
        const double at = hi ? box.hi[a] : box.lo[a], wall = hi ? dom.box.hi[a] : dom.box.lo[a];
        const double length = box.hi[1 - a] - box.lo[1 - a];
        open_side[2 * a + hi] = dom.periodic[a] || at != wall;
        perimeter += length;
        if (open_side[2 * a + hi]) open_perimeter += length;
      }
    for (int sx = 0; sx < 2; ++sx)
      for (int sy = 2; sy < 4; ++sy) open_corners += open_side[sx] && open_side[sy] ? 1 : 0;
    const double band = (open_perimeter * c + open_corners * std::numbers::pi * c * c / 4) / (dx * dx);
    const double allowance = open_perimeter / dx + open_corners * (2 * c / dx + 1);
    const double simple = 2 * perimeter * c / (dx * dx);  // 2 x perimeter x (support + skin) / dx^2
    const auto count = static_cast<double>(halo.size());
    CHECK(std::abs(count - band) <= allowance);
    std::ostringstream line;
    line << "rank " << comm.rank() << " box [" << box.lo[0] << ", " << box.hi[0] << ") x [" << box.lo[1] << ", "
         << box.hi[1] << "): owned " << p.size() << ", halo " << halo.size() << ", band model " << band
         << ", 2 x perimeter x c / dx^2 = " << simple;
    line << '\n';
    const std::string text = line.str();
    const std::vector<char> all = comm.gatherv(std::vector<char>(text.begin(), text.end()));
    if (comm.rank() == 0) {
      std::ostringstream report;
      report << (periodic ? "periodic" : "walls") << ", " << comm.size() << " ranks, c = 4.6 dx\n"
             << std::string(all.begin(), all.end());
      MESSAGE(report.str());
    }
  }
}
