#include "integrate/serial_vector.hpp"

#include <nvector/nvector_serial.h>

#include <cmath>

namespace arksph {

namespace {

struct View {
  sunindextype n;
  double* d;
};
View view(N_Vector v) { return {NV_LENGTH_S(v), NV_DATA_S(v)}; }

// z = a x + b y. Aliasing of z with x or y is allowed: each entry is read before it is written.
// The two factored cases are those of nvector_serial.c (its other special cases, such as a = 1 or
// b = -1, give the same bits as the general formula).
void linear_sum(double a, N_Vector xv, double b, N_Vector yv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  const double* y = NV_DATA_S(yv);
  const bool a_unit = a == 1.0 || a == -1.0, b_unit = b == 1.0 || b == -1.0;
  if (!a_unit && !b_unit && a == b) {
    for (sunindextype i = 0; i < n; ++i) z[i] = a * (x[i] + y[i]);
  } else if (!a_unit && !b_unit && a == -b) {
    for (sunindextype i = 0; i < n; ++i) z[i] = a * (x[i] - y[i]);
  } else {
    for (sunindextype i = 0; i < n; ++i) z[i] = a * x[i] + b * y[i];
  }
}

void constant(double c, N_Vector zv) {
  const auto [n, z] = view(zv);
  for (sunindextype i = 0; i < n; ++i) z[i] = c;
}

void prod(N_Vector xv, N_Vector yv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double *x = NV_DATA_S(xv), *y = NV_DATA_S(yv);
  for (sunindextype i = 0; i < n; ++i) z[i] = x[i] * y[i];
}

void div(N_Vector xv, N_Vector yv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double *x = NV_DATA_S(xv), *y = NV_DATA_S(yv);
  for (sunindextype i = 0; i < n; ++i) z[i] = x[i] / y[i];
}

void scale(double c, N_Vector xv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  for (sunindextype i = 0; i < n; ++i) z[i] = c * x[i];  // c = 1 and -1: the same bits as a copy or negation
}

void abs_value(N_Vector xv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  for (sunindextype i = 0; i < n; ++i) z[i] = std::fabs(x[i]);
}

void inverse(N_Vector xv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  for (sunindextype i = 0; i < n; ++i) z[i] = 1.0 / x[i];
}

void add_const(N_Vector xv, double b, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  for (sunindextype i = 0; i < n; ++i) z[i] = x[i] + b;
}

// Reductions keep the library's single sequential sum (no reassociation), hence its bits.
double dot(N_Vector xv, N_Vector yv) {
  const auto [n, x] = view(xv);
  const double* y = NV_DATA_S(yv);
  double s = 0.0;
  for (sunindextype i = 0; i < n; ++i) s += x[i] * y[i];
  return s;
}

double max_norm(N_Vector xv) {
  const auto [n, x] = view(xv);
  double m = 0.0;
  for (sunindextype i = 0; i < n; ++i)
    if (std::fabs(x[i]) > m) m = std::fabs(x[i]);  // a NaN entry is skipped, as in the library
  return m;
}

double weighted_square_sum(N_Vector xv, N_Vector wv) {
  const auto [n, x] = view(xv);
  const double* w = NV_DATA_S(wv);
  double s = 0.0;
  for (sunindextype i = 0; i < n; ++i) {
    const double p = x[i] * w[i];
    s += p * p;
  }
  return s;
}

double weighted_square_sum_masked(N_Vector xv, N_Vector wv, N_Vector idv) {
  const auto [n, x] = view(xv);
  const double *w = NV_DATA_S(wv), *id = NV_DATA_S(idv);
  double s = 0.0;
  for (sunindextype i = 0; i < n; ++i) {
    if (id[i] > 0.0) {
      const double p = x[i] * w[i];
      s += p * p;
    }
  }
  return s;
}

double wrms_norm(N_Vector xv, N_Vector wv) {
  return std::sqrt(weighted_square_sum(xv, wv) / static_cast<double>(NV_LENGTH_S(xv)));
}

double wrms_norm_masked(N_Vector xv, N_Vector wv, N_Vector idv) {
  return std::sqrt(weighted_square_sum_masked(xv, wv, idv) / static_cast<double>(NV_LENGTH_S(xv)));
}

double minimum(N_Vector xv) {
  const auto [n, x] = view(xv);
  double m = x[0];
  for (sunindextype i = 1; i < n; ++i)
    if (x[i] < m) m = x[i];
  return m;
}

double weighted_l2_norm(N_Vector xv, N_Vector wv) { return std::sqrt(weighted_square_sum(xv, wv)); }

double l1_norm(N_Vector xv) {
  const auto [n, x] = view(xv);
  double s = 0.0;
  for (sunindextype i = 0; i < n; ++i) s += std::fabs(x[i]);
  return s;
}

void compare(double c, N_Vector xv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  for (sunindextype i = 0; i < n; ++i) z[i] = std::fabs(x[i]) >= c ? 1.0 : 0.0;
}

sunbooleantype inverse_test(N_Vector xv, N_Vector zv) {
  const auto [n, z] = view(zv);
  const double* x = NV_DATA_S(xv);
  bool no_zero = true;
  for (sunindextype i = 0; i < n; ++i) {
    if (x[i] == 0.0)
      no_zero = false;
    else
      z[i] = 1.0 / x[i];
  }
  return no_zero ? SUNTRUE : SUNFALSE;
}

// m_i = 1 where x_i violates constraint c_i (2: x > 0, 1: x >= 0, -1: x <= 0, -2: x < 0), else 0.
sunbooleantype constraint_mask(N_Vector cv, N_Vector xv, N_Vector mv) {
  const auto [n, m] = view(mv);
  const double *c = NV_DATA_S(cv), *x = NV_DATA_S(xv);
  bool ok = true;
  for (sunindextype i = 0; i < n; ++i) {
    m[i] = 0.0;
    if (c[i] == 0.0) continue;
    const double xc = x[i] * c[i];
    if ((std::fabs(c[i]) > 1.5 && xc <= 0.0) || (std::fabs(c[i]) > 0.5 && xc < 0.0)) {
      m[i] = 1.0;
      ok = false;
    }
  }
  return ok ? SUNTRUE : SUNFALSE;
}

double min_quotient(N_Vector numv, N_Vector denv) {
  const auto [n, num] = view(numv);
  const double* den = NV_DATA_S(denv);
  bool first = true;
  double m = SUN_BIG_REAL;
  for (sunindextype i = 0; i < n; ++i) {
    if (den[i] == 0.0) continue;
    const double q = num[i] / den[i];
    if (first) {
      m = q;
      first = false;
    } else {
      m = m < q ? m : q;  // SUNMIN(m, q)
    }
  }
  return m;
}

}  // namespace

void use_fast_serial_ops(N_Vector v) {
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = linear_sum;
  o->nvconst = constant;
  o->nvprod = prod;
  o->nvdiv = div;
  o->nvscale = scale;
  o->nvabs = abs_value;
  o->nvinv = inverse;
  o->nvaddconst = add_const;
  o->nvdotprod = dot;
  o->nvmaxnorm = max_norm;
  o->nvwrmsnorm = wrms_norm;
  o->nvwrmsnormmask = wrms_norm_masked;
  o->nvmin = minimum;
  o->nvwl2norm = weighted_l2_norm;
  o->nvl1norm = l1_norm;
  o->nvcompare = compare;
  o->nvinvtest = inverse_test;
  o->nvconstrmask = constraint_mask;
  o->nvminquotient = min_quotient;
  // The "local" reductions of a serial vector are the whole ones.
  o->nvdotprodlocal = dot;
  o->nvmaxnormlocal = max_norm;
  o->nvminlocal = minimum;
  o->nvl1normlocal = l1_norm;
  o->nvinvtestlocal = inverse_test;
  o->nvconstrmasklocal = constraint_mask;
  o->nvminquotientlocal = min_quotient;
  o->nvwsqrsumlocal = weighted_square_sum;
  o->nvwsqrsummasklocal = weighted_square_sum_masked;
}

N_Vector new_serial_vector(sunindextype n, SUNContext ctx) {
  N_Vector v = N_VNew_Serial(n, ctx);
  if (v) use_fast_serial_ops(v);
  return v;
}

}  // namespace arksph
