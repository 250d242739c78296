// Factories of the kernel shapes; one file each, listed once in kernel_registry.cpp.
#pragma once
#include <memory>

#include "kernels/kernel.hpp"

namespace arksph {
std::shared_ptr<const KernelShape> make_cubic_spline();
std::shared_ptr<const KernelShape> make_quartic_spline();
std::shared_ptr<const KernelShape> make_wendland_quintic();
std::shared_ptr<const KernelShape> make_quintic_spline();
}  // namespace arksph
