// C++ callbacks called from SUNDIALS' C code (ARKODE, KINSOL) must not let an exception unwind
// through the C frames: SUNDIALS would be left in the middle of a step, and its frames carry no
// guarantee of unwinding at all. guarded_callback runs the callback's body, stores the first
// exception it throws and returns kCallbackFailed instead, a negative flag: SUNDIALS treats it as
// unrecoverable and returns its own failure flag. The C++ side that called SUNDIALS then calls
// rethrow_callback_error, which rethrows the stored exception, type and message unchanged.
// Every function handed to SUNDIALS is declared noexcept as well: an exception that escaped a
// callback without this guard would end the program (std::terminate) instead of unwinding C frames.
#pragma once
#include <exception>
#include <type_traits>
#include <utility>

namespace arksph {

// The flag a guarded callback returns when its body threw (negative: unrecoverable).
inline constexpr int kCallbackFailed = -1;

// Runs body(): its int result is the callback's flag (a void body gives 0). If body throws, the
// exception is kept in `error` (the first one only: later failures are consequences of it) and
// kCallbackFailed is returned.
template <class Body>
int guarded_callback(std::exception_ptr& error, Body&& body) noexcept {
  try {
    if constexpr (std::is_void_v<std::invoke_result_t<Body&>>) {
      body();
      return 0;
    } else {
      return body();
    }
  } catch (...) {
    if (!error) error = std::current_exception();
    return kCallbackFailed;
  }
}

// Rethrows the exception stored by guarded_callback, if any, and clears `error`.
inline void rethrow_callback_error(std::exception_ptr& error) {
  if (error) std::rethrow_exception(std::exchange(error, nullptr));
}

}  // namespace arksph
