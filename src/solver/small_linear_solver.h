// A dense direct linear solver for the Newton matrix of a small system (n <= 16), for CVODE
// with the small vector of small_vector.h: SUNLinSol_Dense takes only NVECTOR_SERIAL (and its
// threaded kin), and its generic loops cost more than the solve itself at n = 2. The factor is
// an LU with partial pivoting of a fixed-size copy of the matrix, a template on n chosen when
// the solver is made (closed form at n = 2), so the matrix handed to setup is left unchanged.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

namespace musclesim {

// A SUNLINEARSOLVER_DIRECT solver (ID SUNLINEARSOLVER_CUSTOM) for `matrix`, a square
// SUNDenseMatrix of size n with 1 <= n <= kSmallVectorMaxLength (16), and vectors like `y`:
// any vector with an array pointer and length n (a small vector or an NVECTOR_SERIAL).
// Setup factors the matrix it is given (SUNLS_LUFACT_FAIL, positive so recoverable, on a zero
// pivot, the last flag then being the 1-based column, as SUNLinSol_Dense does; SUNLS_ILL_INPUT
// for a matrix that is not dense of size n). Solve solves A x = b with the last factor; x and b
// may be the same vector; the tolerance is ignored. Returns nullptr if `y` or `matrix` do not
// fit these rules or an allocation fails. Free with SUNLinSolFree.
SUNLinearSolver NewSmallDenseSolver(N_Vector y, SUNMatrix matrix, SUNContext context);

}  // namespace musclesim
