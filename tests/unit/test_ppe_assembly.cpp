// The compressed PPE matrix built row by row in parallel (assemble_ppe) against the pair-by-pair
// approximate Laplacian of C&R eq. 19 (apply_laplacian, a serial loop over the same pairs with the
// ghost's pressure read from its source): (A p)_a = -V_a L(p)_a for every row but the pinned one.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "run/setup.hpp"
#include "io/scene_reader.hpp"
#include "projection/ppe_assembly.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
// Walls at the bottom and top, periodic left and right: wall images and periodic images both land
// in their source's column.
const char* kChannel = R"toml(
[scene]
name = "ppe_channel"
[domain]
min = [0.0, 0.0]
max = [1.0, 0.5]
[boundary]
left = { kind = "periodic" }
right = { kind = "periodic" }
[fluid]
spacing = 0.1
viscosity = 0.01
[initial]
velocity = ["sin(2*pi*x)*y", "0.1*cos(2*pi*x)"]
[method]
scheme = "isph"
kernel = "wendland_quintic"
h_over_dx = 2.0
[time]
end = 0.01
dt = 0.01
)toml";
}  // namespace

// Tolerance 1e-13 of max_a sum_b |A_ab| max |p|: round-off of ~50-term sums summed in another order.
TEST_CASE("ppe assembly: the compressed matrix applies the C&R eq. 19 Laplacian") {
  for (const std::string spacing : {"fluid.spacing=0.1", "fluid.spacing=0.025"}) {
    std::ostringstream warnings;
    const Scene scene = read_scene_text(kChannel, "<test>", {spacing}, warnings);
    Model model = build_model(scene);
    const FluidFields& f = testing::fields_at_start(model);
    const PoissonSystem sys = assemble_ppe(f, divergence_cummins_rudman(f), 0.01);
    const std::size_t n = f.n_real;
    REQUIRE(sys.A.rows() == static_cast<long>(n));
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> p(n);
    for (double& v : p) v = u(gen);
    p[0] = 0.0;  // the pinned unknown: its column is dropped from the matrix
    const Eigen::Map<const Eigen::VectorXd> pp(p.data(), static_cast<long>(n));
    const Eigen::VectorXd ap = sys.A * pp;
    const std::vector<double> lap = apply_laplacian(f, p);
    double worst = 0, row_scale = 0;
    for (std::size_t a = 1; a < n; ++a) {
      worst = std::max(worst, std::abs(ap[static_cast<long>(a)] + f.m[a] / f.rho[a] * lap[a]));
      double s = 0;
      for (SparseMatrix::InnerIterator it(sys.A, static_cast<long>(a)); it; ++it) s += std::abs(it.value());
      row_scale = std::max(row_scale, s);
    }
    MESSAGE(spacing, ": N = ", n, ", nonzeros ", sys.A.nonZeros(), ", max |A p + V L(p)| ", worst, " (row scale ", row_scale, ")");
    CHECK(row_scale > 0);
    CHECK(worst <= 1e-13 * row_scale);
    // Row 0 is the identity (P_0 = 0), and the matrix is symmetric to round-off.
    CHECK(ap[0] == doctest::Approx(0.0));
    CHECK((SparseMatrix(sys.A.transpose()) - sys.A).norm() <= 1e-12 * sys.A.norm());
    // Indices strictly increasing within every column: sorted, duplicates merged.
    long unsorted = 0;
    for (long c = 0; c < sys.A.outerSize(); ++c) {
      long last = -1;
      for (SparseMatrix::InnerIterator it(sys.A, c); it; ++it) {
        unsorted += it.row() <= last;
        last = it.row();
      }
    }
    CHECK(unsorted == 0);
  }
}
