// SUNDIALS' NVECTOR test driver (test_nvector.c, compiled from Debian's libsundials-dev
// examples) run on the small vector, as test_nvector_serial.c runs it on NVECTOR_SERIAL: every
// standard, fused, vector-array, local reduction and buffer operation against the driver's
// expected values. Usage: small_vector_driver <length 1..16> <print timing 0|1>. Exit status 1
// if any check fails.
#include <sundials/sundials_math.h>
#include <sundials/sundials_nvector.h>

#include <cstdio>
#include <cstdlib>

#include "solver/small_vector.h"
#include "test_nvector.h"

namespace {

// A vector with every fused and vector-array operation removed, so the driver also checks what
// SUNDIALS' generic fallbacks make of our standard operations.
void DisableFusedOperations(N_Vector v) {
  v->ops->nvlinearcombination = nullptr;
  v->ops->nvscaleaddmulti = nullptr;
  v->ops->nvdotprodmulti = nullptr;
  v->ops->nvlinearsumvectorarray = nullptr;
  v->ops->nvscalevectorarray = nullptr;
  v->ops->nvconstvectorarray = nullptr;
  v->ops->nvwrmsnormvectorarray = nullptr;
  v->ops->nvwrmsnormmaskvectorarray = nullptr;
  v->ops->nvscaleaddmultivectorarray = nullptr;
  v->ops->nvlinearcombinationvectorarray = nullptr;
}

int RunDriver(sunindextype length) {
  using musclesim::NewSmallVector;
  const int n = static_cast<int>(length);
  int fails = 0;

  N_Vector x = NewSmallVector(n, sunctx);
  N_Vector w = N_VCloneEmpty(x);
  N_Vector y = N_VClone(x);
  N_Vector z = N_VClone(x);
  N_Vector u = NewSmallVector(n, sunctx);
  N_Vector v = NewSmallVector(n, sunctx);
  if (x == nullptr || w == nullptr || y == nullptr || z == nullptr || u == nullptr ||
      v == nullptr) {
    std::printf("FAIL: unable to create the vectors\n");
    return 1;
  }
  DisableFusedOperations(u);

  fails += Test_N_VGetVectorID(x, SUNDIALS_NVEC_CUSTOM, 0);
  fails += Test_N_VGetLength(x, 0);
  fails += Test_N_VGetCommunicator(x, nullptr, 0);

  fails += Test_N_VCloneEmpty(x, 0);
  fails += Test_N_VClone(x, length, 0);
  fails += Test_N_VCloneEmptyVectorArray(5, x, 0);
  fails += Test_N_VCloneVectorArray(5, x, length, 0);
  fails += Test_N_VSetArrayPointer(w, length, 0);
  fails += Test_N_VGetArrayPointer(x, length, 0);

  std::printf("\nTesting standard vector operations:\n\n");
  fails += Test_N_VConst(x, length, 0);
  fails += Test_N_VLinearSum(x, y, z, length, 0);
  fails += Test_N_VProd(x, y, z, length, 0);
  fails += Test_N_VDiv(x, y, z, length, 0);
  fails += Test_N_VScale(x, z, length, 0);
  fails += Test_N_VAbs(x, z, length, 0);
  fails += Test_N_VInv(x, z, length, 0);
  fails += Test_N_VAddConst(x, z, length, 0);
  fails += Test_N_VDotProd(x, y, length, 0);
  fails += Test_N_VMaxNorm(x, length, 0);
  fails += Test_N_VWrmsNorm(x, y, length, 0);
  fails += Test_N_VWrmsNormMask(x, y, z, length, 0);
  fails += Test_N_VMin(x, length, 0);
  fails += Test_N_VWL2Norm(x, y, length, 0);
  fails += Test_N_VL1Norm(x, length, 0);
  // the driver's InvTest, Compare and ConstrMask checks need 2, 3 and 7 entries (it is run
  // at 1000 and more): shorter vectors skip them here, small_vector_test compares them
  // with NVECTOR_SERIAL at every length
  if (length >= 3) fails += Test_N_VCompare(x, z, length, 0);
  if (length >= 2) fails += Test_N_VInvTest(x, z, length, 0);
  if (length >= 7) fails += Test_N_VConstrMask(x, y, z, length, 0);
  fails += Test_N_VMinQuotient(x, y, length, 0);

  // u without, v with our fused and vector-array operations
  for (N_Vector fused : {u, v}) {
    std::printf("\nTesting fused and vector array operations (%s):\n\n",
                fused == u ? "SUNDIALS' fallbacks" : "ours");
    fails += Test_N_VLinearCombination(fused, length, 0);
    fails += Test_N_VScaleAddMulti(fused, length, 0);
    fails += Test_N_VDotProdMulti(fused, length, 0);
    fails += Test_N_VLinearSumVectorArray(fused, length, 0);
    fails += Test_N_VScaleVectorArray(fused, length, 0);
    fails += Test_N_VConstVectorArray(fused, length, 0);
    fails += Test_N_VWrmsNormVectorArray(fused, length, 0);
    fails += Test_N_VWrmsNormMaskVectorArray(fused, length, 0);
    fails += Test_N_VScaleAddMultiVectorArray(fused, length, 0);
    fails += Test_N_VLinearCombinationVectorArray(fused, length, 0);
  }

  std::printf("\nTesting local reduction operations:\n\n");
  fails += Test_N_VDotProdLocal(x, y, length, 0);
  fails += Test_N_VMaxNormLocal(x, length, 0);
  fails += Test_N_VMinLocal(x, length, 0);
  fails += Test_N_VL1NormLocal(x, length, 0);
  fails += Test_N_VWSqrSumLocal(x, y, length, 0);
  fails += Test_N_VWSqrSumMaskLocal(x, y, z, length, 0);
  if (length >= 2) fails += Test_N_VInvTestLocal(x, z, length, 0);
  if (length >= 7) fails += Test_N_VConstrMaskLocal(x, y, z, length, 0);
  fails += Test_N_VMinQuotientLocal(x, y, length, 0);
  fails += Test_N_VDotProdMultiLocal(v, length, 0);

  std::printf("\nTesting buffer operations:\n\n");
  fails += Test_N_VBufSize(x, length, 0);
  fails += Test_N_VBufPack(x, length, 0);
  fails += Test_N_VBufUnpack(x, length, 0);

  for (N_Vector vector : {w, x, y, z, u, v}) N_VDestroy(vector);
  return fails;
}

}  // namespace

int main(int argc, char* argv[]) {
  if (argc < 3) {
    std::printf("ERROR: two arguments required: vector length, print timing\n");
    return 2;
  }
  const long length = std::atol(argv[1]);
  if (length < 1 || length > musclesim::kSmallVectorMaxLength) {
    std::printf("ERROR: the length must be in [1, %d]\n", musclesim::kSmallVectorMaxLength);
    return 2;
  }
  if (Test_Init(nullptr) != 0) return 1;
  SetTiming(std::atoi(argv[2]), 0);
  std::printf("Testing the small N_Vector, length %ld\n", length);

  const int fails = RunDriver(static_cast<sunindextype>(length));
  if (fails != 0) {
    std::printf("FAIL: the small N_Vector failed %d tests\n\n", fails);
  } else {
    std::printf("SUCCESS: the small N_Vector passed all tests\n\n");
  }
  Test_Finalize();
  // not the count itself: an exit status is taken modulo 256
  return fails != 0 ? 1 : 0;
}

// ---------------------------------------------------------------------------------------------
// what the driver asks of an implementation (declared in test_nvector.h)

int check_ans(realtype ans, N_Vector X, sunindextype local_length) {
  const realtype* data = N_VGetArrayPointer(X);
  int failures = 0;
  for (sunindextype i = 0; i < local_length; ++i) failures += SUNRCompare(data[i], ans);
  return failures > 0 ? 1 : 0;
}

booleantype has_data(N_Vector X) { return N_VGetArrayPointer(X) != nullptr ? SUNTRUE : SUNFALSE; }

void set_element(N_Vector X, sunindextype i, realtype val) { set_element_range(X, i, i, val); }

void set_element_range(N_Vector X, sunindextype is, sunindextype ie, realtype val) {
  realtype* data = N_VGetArrayPointer(X);
  for (sunindextype i = is; i <= ie; ++i) data[i] = val;
}

realtype get_element(N_Vector X, sunindextype i) { return N_VGetArrayPointer(X)[i]; }

// one process: its own time is the maximum
double max_time(N_Vector, double time) { return time; }

// no device to wait for
void sync_device(N_Vector) {}
