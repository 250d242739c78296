// The compiled-for-speed serial vector operations (integrate/serial_vector.cpp) against the library's
// own nvector_serial functions, on the same inputs: every result must be bit for bit the library's
// (no tolerance: the replacements claim the same arithmetic in the same order, and any reordering of
// a sum or factoring of a product shows up in the last bits of random data).
#include <doctest/doctest.h>
#include <nvector/nvector_serial.h>

#include <cstring>
#include <random>
#include <vector>

#include "integrate/serial_vector.hpp"
#include "test_support.hpp"

using namespace arksph;

namespace {
struct Vectors {
  SUNContext ctx = nullptr;
  static constexpr sunindextype n = 1001;  // odd: a vectorised loop has a remainder
  std::vector<N_Vector> fast, lib;         // fast[k] and lib[k] hold the same values
  Vectors() {
    SUNContext_Create(nullptr, &ctx);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> value(-2.0, 2.0);
    for (int k = 0; k < 4; ++k) {
      fast.push_back(new_serial_vector(n, ctx));
      lib.push_back(N_VNew_Serial(n, ctx));
      for (sunindextype i = 0; i < n; ++i) {
        // Some exact zeros and ones, which the masks, tests and quotients treat specially.
        const double v = i % 37 == 0 ? 0.0 : i % 41 == 0 ? 1.0 : value(rng);
        NV_Ith_S(fast[k], i) = NV_Ith_S(lib[k], i) = v;
      }
    }
  }
  ~Vectors() {
    for (N_Vector v : fast) N_VDestroy(v);
    for (N_Vector v : lib) N_VDestroy(v);
    SUNContext_Free(&ctx);
  }
  bool same(int k) const { return std::memcmp(NV_DATA_S(fast[k]), NV_DATA_S(lib[k]), n * sizeof(double)) == 0; }
};

bool bits_equal(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST_CASE("serial vector: a clone inherits the fast operations (so ARKODE's work vectors get them)") {
  Vectors v;
  N_Vector c = N_VClone(v.fast[0]);
  // Function pointers compared as booleans: doctest cannot print them.
  CHECK((c->ops->nvlinearsum == v.fast[0]->ops->nvlinearsum));
  CHECK((c->ops->nvwrmsnorm == v.fast[0]->ops->nvwrmsnorm));
  CHECK((c->ops->nvlinearsum != v.lib[0]->ops->nvlinearsum));
  CHECK(N_VGetLength(c) == Vectors::n);
  N_VDestroy(c);
}

TEST_CASE("serial vector: linear sum gives the library's bits in each of its special cases, aliased or not") {
  const double coeffs[] = {1.0, -1.0, 0.0, 0.3, -0.3, 2.5, 0.1};
  for (double a : coeffs)
    for (double b : coeffs)
      for (int alias = 0; alias < 3; ++alias) {  // z separate, z = x, z = y
        Vectors v;
        const int z = alias == 0 ? 2 : alias == 1 ? 0 : 1;
        N_VLinearSum(a, v.fast[0], b, v.fast[1], v.fast[z]);
        N_VLinearSum_Serial(a, v.lib[0], b, v.lib[1], v.lib[z]);
        INFO("a = " << a << ", b = " << b << ", alias " << alias);
        CHECK(v.same(z));
      }
}

TEST_CASE("serial vector: element-wise operations give the library's bits") {
  // The data hold exact zeros, so N_VDiv and N_VInv divide by zero on purpose (the infinities and
  // NaNs must match the library's bit for bit): no floating-point traps here.
  const testing::FpTrapsOff traps_off;
  for (double c : {1.0, -1.0, 0.7, 0.0}) {
    for (int alias = 0; alias < 2; ++alias) {
      Vectors v;
      const int z = alias ? 0 : 2;
      N_VScale(c, v.fast[0], v.fast[z]);
      N_VScale_Serial(c, v.lib[0], v.lib[z]);
      CHECK(v.same(z));
      N_VAddConst(v.fast[1], c, v.fast[z]);
      N_VAddConst_Serial(v.lib[1], c, v.lib[z]);
      CHECK(v.same(z));
      N_VCompare(c, v.fast[1], v.fast[z]);
      N_VCompare_Serial(c, v.lib[1], v.lib[z]);
      CHECK(v.same(z));
    }
  }
  Vectors v;
  N_VConst(0.25, v.fast[3]);
  N_VConst_Serial(0.25, v.lib[3]);
  CHECK(v.same(3));
  N_VProd(v.fast[0], v.fast[1], v.fast[2]);
  N_VProd_Serial(v.lib[0], v.lib[1], v.lib[2]);
  CHECK(v.same(2));
  N_VDiv(v.fast[0], v.fast[1], v.fast[2]);
  N_VDiv_Serial(v.lib[0], v.lib[1], v.lib[2]);
  CHECK(v.same(2));
  N_VAbs(v.fast[0], v.fast[2]);
  N_VAbs_Serial(v.lib[0], v.lib[2]);
  CHECK(v.same(2));
  N_VInv(v.fast[1], v.fast[2]);
  N_VInv_Serial(v.lib[1], v.lib[2]);
  CHECK(v.same(2));
  CHECK(N_VInvTest(v.fast[0], v.fast[3]) == N_VInvTest_Serial(v.lib[0], v.lib[3]));
  CHECK(v.same(3));
  // Constraint codes -2, -1, 0, 1, 2 spread over the entries.
  for (sunindextype i = 0; i < Vectors::n; ++i) NV_Ith_S(v.fast[2], i) = NV_Ith_S(v.lib[2], i) = double(i % 5) - 2.0;
  CHECK(N_VConstrMask(v.fast[2], v.fast[0], v.fast[3]) == N_VConstrMask_Serial(v.lib[2], v.lib[0], v.lib[3]));
  CHECK(v.same(3));
}

TEST_CASE("serial vector: reductions and norms give the library's bits") {
  Vectors v;
  NV_Ith_S(v.fast[2], 7) = NV_Ith_S(v.lib[2], 7) = -1.0;  // the mask of the masked norm: id > 0 only
  CHECK(bits_equal(N_VDotProd(v.fast[0], v.fast[1]), N_VDotProd_Serial(v.lib[0], v.lib[1])));
  CHECK(bits_equal(N_VMaxNorm(v.fast[0]), N_VMaxNorm_Serial(v.lib[0])));
  CHECK(bits_equal(N_VWrmsNorm(v.fast[0], v.fast[1]), N_VWrmsNorm_Serial(v.lib[0], v.lib[1])));
  CHECK(bits_equal(N_VWrmsNormMask(v.fast[0], v.fast[1], v.fast[2]),
                   N_VWrmsNormMask_Serial(v.lib[0], v.lib[1], v.lib[2])));
  CHECK(bits_equal(N_VMin(v.fast[0]), N_VMin_Serial(v.lib[0])));
  CHECK(bits_equal(N_VWL2Norm(v.fast[0], v.fast[1]), N_VWL2Norm_Serial(v.lib[0], v.lib[1])));
  CHECK(bits_equal(N_VL1Norm(v.fast[0]), N_VL1Norm_Serial(v.lib[0])));
  CHECK(bits_equal(N_VMinQuotient(v.fast[0], v.fast[1]), N_VMinQuotient_Serial(v.lib[0], v.lib[1])));
  CHECK(bits_equal(N_VWSqrSumLocal(v.fast[0], v.fast[1]), N_VWSqrSumLocal_Serial(v.lib[0], v.lib[1])));
  // A linear combination of three vectors (ARKODE's stage sums) goes through the generic fallback,
  // which the fast scale and linear sum must reproduce.
  double c[3] = {0.5, -0.25, 1.0 / 3.0};
  N_Vector xf[3] = {v.fast[0], v.fast[1], v.fast[2]}, xl[3] = {v.lib[0], v.lib[1], v.lib[2]};
  N_VLinearCombination(3, c, xf, v.fast[3]);
  N_VLinearCombination(3, c, xl, v.lib[3]);
  CHECK(v.same(3));
}
