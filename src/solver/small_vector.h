// An N_Vector for the few states of one actuator (1 to 16 entries). NVECTOR_SERIAL spends most
// of an operation on 2 entries in generic branches and calls; here every operation is a
// template on the length, chosen once when the vector is made, so its loops are unrolled and an
// operation costs a handful of instructions. Results are those of NVECTOR_SERIAL, aliasing
// rules included (docs/solver.md lists what CVODE calls and what is implemented).
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

namespace musclesim {

inline constexpr int kSmallVectorMaxLength = 16;

// A new vector of `length` entries (1 <= length <= kSmallVectorMaxLength, asserted; outside
// that range the result is nullptr) whose data it owns, uninitialised, in the same allocation
// as its content. Its ID is SUNDIALS_NVEC_CUSTOM; every standard, fused, vector-array, local
// reduction and buffer operation is set. N_VGetArrayPointer / N_VSetArrayPointer work as for
// NVECTOR_SERIAL: a vector made by N_VCloneEmpty has no data until one is set, and set data
// stay the caller's. Returns nullptr if an allocation fails. Free with N_VDestroy.
N_Vector NewSmallVector(int length, SUNContext context);

// Whether `v` was made by NewSmallVector (or cloned from one).
bool IsSmallVector(N_Vector v);

}  // namespace musclesim
