// The small vector against NVECTOR_SERIAL holding the same data (the operations CVODE calls
// most, aliasing included), and the small dense solver against Eigen's FullPivLU. SUNDIALS'
// own drivers (tests/sundials_drivers/) cover every operation against their expected values.
#include <cvodes/cvodes.h>
#include <gtest/gtest.h>
#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <vector>

#include "solver/small_linear_solver.h"
#include "solver/small_vector.h"

namespace musclesim {
namespace {

class SundialsContext {
 public:
  SundialsContext() { SUNContext_Create(nullptr, &context_); }
  ~SundialsContext() { SUNContext_Free(&context_); }
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;
  SUNContext get() const { return context_; }

 private:
  SUNContext context_ = nullptr;
};

// The same data in a small vector and in an NVECTOR_SERIAL.
struct VectorPair {
  N_Vector small = nullptr;
  N_Vector serial = nullptr;
};

// Every comparison is with EXPECT_DOUBLE_EQ (4 ulps): the small vector uses serial's formulas
// in serial's order, so results agree to rounding; the slack allows for a compiler contracting
// a product and a sum into one FMA in one library and not in the other.
void ExpectSameData(const VectorPair& pair, int n) {
  const double* small = N_VGetArrayPointer(pair.small);
  const double* serial = N_VGetArrayPointer(pair.serial);
  for (int i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(small[i], serial[i]) << "entry " << i;
}

class SmallVectorOps : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override { n_ = GetParam(); }
  void TearDown() override {
    for (VectorPair& pair : pairs_) {
      N_VDestroy(pair.small);
      N_VDestroy(pair.serial);
    }
  }

  // A pair of vectors with entries uniform in [low, high], some of them 0 if `zeros`.
  VectorPair& Random(double low, double high, bool zeros = false) {
    VectorPair pair{NewSmallVector(n_, context_.get()), N_VNew_Serial(n_, context_.get())};
    std::uniform_real_distribution<double> uniform(low, high);
    for (int i = 0; i < n_; ++i) {
      const double value = zeros && i % 3 == 1 ? 0.0 : uniform(engine_);
      N_VGetArrayPointer(pair.small)[i] = value;
      N_VGetArrayPointer(pair.serial)[i] = value;
    }
    pairs_.push_back(pair);
    return pairs_.back();
  }

  int n_ = 0;
  SundialsContext context_;
  std::mt19937 engine_{20240611};
  std::deque<VectorPair> pairs_;  // a deque: Random hands out references that must stay valid
};

TEST_P(SmallVectorOps, IsSmallVectorTellsOursAndClonesFromSerial) {
  VectorPair& x = Random(-1, 1);
  N_Vector clone = N_VClone(x.small);
  EXPECT_TRUE(IsSmallVector(x.small));
  EXPECT_TRUE(IsSmallVector(clone));
  EXPECT_FALSE(IsSmallVector(x.serial));
  EXPECT_EQ(N_VGetLength(clone), n_);
  EXPECT_EQ(N_VGetVectorID(clone), SUNDIALS_NVEC_CUSTOM);
  N_VDestroy(clone);
}

TEST_P(SmallVectorOps, LinearSumMatchesSerialForEveryCaseAndAlias) {
  // serial singles out a or b = +-1, a = b and a = -b, and z aliasing x or y
  const double coefficients[][2] = {{1, 1},     {1, -1},     {-1, 1},     {-1, -1},
                                    {1, 0.3},   {0.3, 1},    {-1, 0.7},   {0.7, -1},
                                    {0.4, 0.4}, {0.4, -0.4}, {2.5, -0.3}, {0, 0}};
  for (const auto& [a, b] : coefficients) {
    for (int alias = 0; alias < 3; ++alias) {
      VectorPair& x = Random(-2, 2);
      VectorPair& y = Random(-2, 2);
      VectorPair& z = alias == 0 ? Random(-2, 2) : alias == 1 ? x : y;
      N_VLinearSum(a, x.small, b, y.small, z.small);
      N_VLinearSum(a, x.serial, b, y.serial, z.serial);
      SCOPED_TRACE(testing::Message() << "a " << a << " b " << b << " alias " << alias);
      ExpectSameData(z, n_);
    }
  }
}

TEST_P(SmallVectorOps, ElementwiseOperationsMatchSerial) {
  VectorPair& x = Random(-3, 3);
  VectorPair& y = Random(0.5, 2);
  VectorPair& z = Random(-1, 1);
  N_VScale(-1.7, x.small, z.small);
  N_VScale(-1.7, x.serial, z.serial);
  ExpectSameData(z, n_);
  N_VScale(0.3, z.small, z.small);  // in place, as CVODE scales its history arrays
  N_VScale(0.3, z.serial, z.serial);
  ExpectSameData(z, n_);
  N_VProd(x.small, y.small, z.small);
  N_VProd(x.serial, y.serial, z.serial);
  ExpectSameData(z, n_);
  N_VDiv(x.small, y.small, z.small);
  N_VDiv(x.serial, y.serial, z.serial);
  ExpectSameData(z, n_);
  N_VAbs(x.small, z.small);
  N_VAbs(x.serial, z.serial);
  ExpectSameData(z, n_);
  N_VInv(y.small, z.small);
  N_VInv(y.serial, z.serial);
  ExpectSameData(z, n_);
  N_VAddConst(x.small, 0.25, z.small);
  N_VAddConst(x.serial, 0.25, z.serial);
  ExpectSameData(z, n_);
  N_VCompare(1.0, x.small, z.small);
  N_VCompare(1.0, x.serial, z.serial);
  ExpectSameData(z, n_);
  N_VConst(4.5, z.small);
  N_VConst(4.5, z.serial);
  ExpectSameData(z, n_);
}

TEST_P(SmallVectorOps, NormsAndReductionsMatchSerial) {
  VectorPair& x = Random(-3, 3);
  VectorPair& w = Random(0.1, 10);
  VectorPair& mask = Random(-1, 1);
  EXPECT_DOUBLE_EQ(N_VWrmsNorm(x.small, w.small), N_VWrmsNorm(x.serial, w.serial));
  EXPECT_DOUBLE_EQ(N_VWrmsNormMask(x.small, w.small, mask.small),
                   N_VWrmsNormMask(x.serial, w.serial, mask.serial));
  EXPECT_DOUBLE_EQ(N_VWL2Norm(x.small, w.small), N_VWL2Norm(x.serial, w.serial));
  EXPECT_DOUBLE_EQ(N_VMaxNorm(x.small), N_VMaxNorm(x.serial));
  EXPECT_DOUBLE_EQ(N_VL1Norm(x.small), N_VL1Norm(x.serial));
  EXPECT_DOUBLE_EQ(N_VMin(x.small), N_VMin(x.serial));
  EXPECT_DOUBLE_EQ(N_VDotProd(x.small, w.small), N_VDotProd(x.serial, w.serial));
}

TEST_P(SmallVectorOps, TestsAndMasksMatchSerial) {
  VectorPair& x = Random(-1, 1, /*zeros=*/true);
  VectorPair& z = Random(5, 6);
  EXPECT_EQ(N_VInvTest(x.small, z.small), N_VInvTest(x.serial, z.serial));
  ExpectSameData(z, n_);  // a zero's entry of z left as it was, the others inverted

  VectorPair& denominator = Random(-2, 2, /*zeros=*/true);
  EXPECT_DOUBLE_EQ(N_VMinQuotient(x.small, denominator.small),
                   N_VMinQuotient(x.serial, denominator.serial));

  // constraints -2, -1, 0, 1, 2 in turn against values of both signs and zeros
  VectorPair& constraints = Random(0, 1);
  for (int i = 0; i < n_; ++i) {
    N_VGetArrayPointer(constraints.small)[i] = (i % 5) - 2.0;
    N_VGetArrayPointer(constraints.serial)[i] = (i % 5) - 2.0;
  }
  VectorPair& m = Random(0, 1);
  EXPECT_EQ(N_VConstrMask(constraints.small, x.small, m.small),
            N_VConstrMask(constraints.serial, x.serial, m.serial));
  ExpectSameData(m, n_);
}

TEST_P(SmallVectorOps, LinearCombinationMatchesSerialWithZAliasingTheFirstVector) {
  // CVODE's prediction and correction combine up to 6 history arrays, often into the first
  for (int nvec = 1; nvec <= 6; ++nvec) {
    for (int alias = 0; alias < 3; ++alias) {
      std::vector<double> c(nvec);
      for (int i = 0; i < nvec; ++i) c[i] = 0.5 - 0.3 * i;
      if (alias == 2) c[0] = 1.0;  // serial's in-place sum into x_0
      std::vector<N_Vector> small(nvec), serial(nvec);
      for (int i = 0; i < nvec; ++i) {
        VectorPair& x = Random(-1, 1);
        small[i] = x.small;
        serial[i] = x.serial;
      }
      VectorPair z = alias == 0 ? Random(-1, 1) : VectorPair{small[0], serial[0]};
      EXPECT_EQ(N_VLinearCombination(nvec, c.data(), small.data(), z.small), 0);
      EXPECT_EQ(N_VLinearCombination(nvec, c.data(), serial.data(), z.serial), 0);
      SCOPED_TRACE(testing::Message() << "nvec " << nvec << " alias " << alias);
      ExpectSameData(z, n_);
    }
  }
}

TEST_P(SmallVectorOps, ScaleAddMultiAndDotProdMultiMatchSerial) {
  for (int nvec = 1; nvec <= 4; ++nvec) {
    for (bool in_place : {false, true}) {
      VectorPair& x = Random(-1, 1);
      std::vector<double> a(nvec);
      std::vector<N_Vector> y_small(nvec), y_serial(nvec), z_small(nvec), z_serial(nvec);
      std::vector<VectorPair*> z(nvec);
      for (int i = 0; i < nvec; ++i) {
        a[i] = 1.5 - i;
        VectorPair& y = Random(-1, 1);
        z[i] = in_place ? &y : &Random(-1, 1);
        y_small[i] = y.small;
        y_serial[i] = y.serial;
        z_small[i] = z[i]->small;
        z_serial[i] = z[i]->serial;
      }
      EXPECT_EQ(N_VScaleAddMulti(nvec, a.data(), x.small, y_small.data(), z_small.data()), 0);
      EXPECT_EQ(N_VScaleAddMulti(nvec, a.data(), x.serial, y_serial.data(), z_serial.data()), 0);
      for (int i = 0; i < nvec; ++i) ExpectSameData(*z[i], n_);

      std::vector<double> dots_small(nvec), dots_serial(nvec);
      EXPECT_EQ(N_VDotProdMulti(nvec, x.small, y_small.data(), dots_small.data()), 0);
      EXPECT_EQ(N_VDotProdMulti(nvec, x.serial, y_serial.data(), dots_serial.data()), 0);
      for (int i = 0; i < nvec; ++i) EXPECT_DOUBLE_EQ(dots_small[i], dots_serial[i]);
    }
  }
}

TEST_P(SmallVectorOps, WrmsNormVectorArrayMatchesSerial) {
  constexpr int kCount = 3;
  std::vector<N_Vector> x_small, x_serial, w_small, w_serial;
  for (int i = 0; i < kCount; ++i) {
    VectorPair& x = Random(-2, 2);
    VectorPair& w = Random(0.1, 3);
    x_small.push_back(x.small);
    x_serial.push_back(x.serial);
    w_small.push_back(w.small);
    w_serial.push_back(w.serial);
  }
  double small[kCount], serial[kCount];
  EXPECT_EQ(N_VWrmsNormVectorArray(kCount, x_small.data(), w_small.data(), small), 0);
  EXPECT_EQ(N_VWrmsNormVectorArray(kCount, x_serial.data(), w_serial.data(), serial), 0);
  for (int i = 0; i < kCount; ++i) EXPECT_DOUBLE_EQ(small[i], serial[i]);
}

TEST_P(SmallVectorOps, EmptyCloneWorksOnAMatrixColumnAsTheDifferenceJacobianUsesIt) {
  // cvLsDenseDQJac: N_VCloneEmpty, N_VSetArrayPointer on column j, difference into it
  SUNMatrix matrix = SUNDenseMatrix(n_, n_, context_.get());
  VectorPair& x = Random(-1, 1);
  VectorPair& y = Random(-1, 1);
  N_Vector column = N_VCloneEmpty(x.small);
  ASSERT_NE(column, nullptr);
  EXPECT_EQ(N_VGetArrayPointer(column), nullptr);
  const int j = n_ - 1;
  N_VSetArrayPointer(SUNDenseMatrix_Column(matrix, j), column);
  EXPECT_EQ(N_VGetArrayPointer(column), SUNDenseMatrix_Column(matrix, j));
  N_VLinearSum(2.0, x.small, -2.0, y.small, column);
  for (int i = 0; i < n_; ++i) {
    const double expected =
        2.0 * (N_VGetArrayPointer(x.serial)[i] - N_VGetArrayPointer(y.serial)[i]);
    EXPECT_DOUBLE_EQ(SM_ELEMENT_D(matrix, i, j), expected);
  }
  N_VDestroy(column);  // the column stays the matrix's
  SUNMatDestroy(matrix);
}

INSTANTIATE_TEST_SUITE_P(Lengths, SmallVectorOps, ::testing::Values(1, 2, 3, 7, 16));

// ---------------------------------------------------------------------------------------------
// the small dense solver

class SmallDenseSolver : public ::testing::Test {
 protected:
  // Solves `a` x = `b` with the small solver on small vectors; the setup flag in `setup_flag`.
  Eigen::VectorXd Solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, int* setup_flag,
                        sunindextype* last_flag = nullptr) {
    const int n = static_cast<int>(a.rows());
    SUNMatrix matrix = SUNDenseMatrix(n, n, context_.get());
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) SM_ELEMENT_D(matrix, i, j) = a(i, j);
    }
    N_Vector x = NewSmallVector(n, context_.get());
    N_Vector rhs = N_VClone(x);
    for (int i = 0; i < n; ++i) N_VGetArrayPointer(rhs)[i] = b(i);
    SUNLinearSolver solver = NewSmallDenseSolver(x, matrix, context_.get());
    EXPECT_NE(solver, nullptr);
    Eigen::VectorXd solution = Eigen::VectorXd::Constant(n, std::nan(""));
    if (solver != nullptr) {
      EXPECT_EQ(SUNLinSolInitialize(solver), SUNLS_SUCCESS);
      *setup_flag = SUNLinSolSetup(solver, matrix);
      if (last_flag != nullptr) *last_flag = SUNLinSolLastFlag(solver);
      if (*setup_flag == SUNLS_SUCCESS) {
        EXPECT_EQ(SUNLinSolSolve(solver, matrix, x, rhs, 0.0), SUNLS_SUCCESS);
        for (int i = 0; i < n; ++i) solution(i) = N_VGetArrayPointer(x)[i];
        // b and x one vector, as CVODE solves in place
        EXPECT_EQ(SUNLinSolSolve(solver, matrix, rhs, rhs, 0.0), SUNLS_SUCCESS);
        for (int i = 0; i < n; ++i) EXPECT_EQ(N_VGetArrayPointer(rhs)[i], solution(i));
      }
      SUNLinSolFree(solver);
    }
    N_VDestroy(x);
    N_VDestroy(rhs);
    SUNMatDestroy(matrix);
    return solution;
  }

  Eigen::MatrixXd RandomMatrix(int n) {
    std::uniform_real_distribution<double> uniform(-1, 1);
    Eigen::MatrixXd a(n, n);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) a(i, j) = uniform(engine_);
    }
    return a;
  }

  SundialsContext context_;
  std::mt19937 engine_{7};
};

TEST_F(SmallDenseSolver, SolvesRandomSystemsLikeFullPivLu) {
  for (int n : {2, 16}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::MatrixXd a = RandomMatrix(n);
      Eigen::VectorXd b(n);
      for (int i = 0; i < n; ++i) b(i) = std::uniform_real_distribution<double>(-1, 1)(engine_);
      int flag = -1;
      const Eigen::VectorXd x = Solve(a, b, &flag);
      ASSERT_EQ(flag, SUNLS_SUCCESS);
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
      const Eigen::VectorXd reference = lu.solve(b);
      // both are backward stable, so each is within cond(A) * a few n eps of the exact
      // solution; 10 n eps cond(A) covers the two errors together
      const double condition = a.norm() * a.inverse().norm();
      const double tolerance = 10.0 * n * 2.2e-16 * condition;
      EXPECT_LE((x - reference).norm(), tolerance * reference.norm())
          << "n " << n << " trial " << trial << " cond " << condition;
    }
  }
}

TEST_F(SmallDenseSolver, PivotsOnATinyLeadingEntry) {
  // without a row swap, 1/eps swamps the second row and x_0 comes out 0 instead of 1
  Eigen::Matrix2d a;
  a << 1e-20, 1, 1, 1;
  const Eigen::Vector2d b(1, 2);
  int flag = -1;
  const Eigen::VectorXd x = Solve(a, b, &flag);
  ASSERT_EQ(flag, SUNLS_SUCCESS);
  const Eigen::Vector2d reference = a.fullPivLu().solve(b);
  // cond(A) is about 2.6: a few eps
  EXPECT_NEAR(x(0), reference(0), 1e-15);
  EXPECT_NEAR(x(1), reference(1), 1e-15);
}

TEST_F(SmallDenseSolver, SingularMatrixGivesRecoverableFactorFailure) {
  // 2x2: the second row twice the first, and a zero first column
  Eigen::Matrix2d dependent_rows;
  dependent_rows << 1, 2, 2, 4;
  Eigen::Matrix2d zero_column;
  zero_column << 0, 1, 0, 2;
  // 16x16: row 5 repeated as row 11
  Eigen::MatrixXd repeated_row = RandomMatrix(16);
  repeated_row.row(11) = repeated_row.row(5);

  for (const Eigen::MatrixXd& a :
       {Eigen::MatrixXd(dependent_rows), Eigen::MatrixXd(zero_column), repeated_row}) {
    ASSERT_LT(a.fullPivLu().rank(), a.rows());  // singular, says Eigen
    int flag = -1;
    sunindextype last_flag = 0;
    Solve(a, Eigen::VectorXd::Ones(a.rows()), &flag, &last_flag);
    EXPECT_EQ(flag, SUNLS_LUFACT_FAIL);
    EXPECT_GT(SUNLS_LUFACT_FAIL, 0);  // CVODE retries with a smaller step on a positive flag
    // the 1-based column of the zero pivot, as SUNLinSol_Dense reports it
    EXPECT_GE(last_flag, 1);
    EXPECT_LE(last_flag, a.rows());
  }
  int flag = -1;
  sunindextype last_flag = 0;
  Solve(zero_column, Eigen::Vector2d::Ones(), &flag, &last_flag);
  EXPECT_EQ(last_flag, 1);
  Solve(dependent_rows, Eigen::Vector2d::Ones(), &flag, &last_flag);
  EXPECT_EQ(last_flag, 2);
}

TEST_F(SmallDenseSolver, AcceptsSerialVectorsAndRejectsMismatches) {
  SUNMatrix matrix = SUNDenseMatrix(3, 3, context_.get());
  SUNMatrix wide = SUNDenseMatrix(3, 4, context_.get());
  N_Vector serial = N_VNew_Serial(3, context_.get());
  N_Vector short_vector = NewSmallVector(2, context_.get());
  SUNLinearSolver solver = NewSmallDenseSolver(serial, matrix, context_.get());
  EXPECT_NE(solver, nullptr);
  EXPECT_EQ(SUNLinSolGetType(solver), SUNLINEARSOLVER_DIRECT);
  SUNLinSolFree(solver);
  EXPECT_EQ(NewSmallDenseSolver(short_vector, matrix, context_.get()), nullptr);
  EXPECT_EQ(NewSmallDenseSolver(serial, wide, context_.get()), nullptr);
  N_VDestroy(serial);
  N_VDestroy(short_vector);
  SUNMatDestroy(matrix);
  SUNMatDestroy(wide);
}

}  // namespace
}  // namespace musclesim

// ---------------------------------------------------------------------------------------------
// both under CVODE, as the simulation will use them

namespace musclesim {
namespace {

struct Oscillator {
  double stiffness = 4.0;  // k [1/s^2]
  double damping = 0.4;    // c [1/s]
};

// y0' = y1, y1' = -k y0 - c y1
int OscillatorRhs(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& oscillator = *static_cast<const Oscillator*>(data);
  const double* yd = N_VGetArrayPointer(y);
  double* dd = N_VGetArrayPointer(ydot);
  dd[0] = yd[1];
  dd[1] = -oscillator.stiffness * yd[0] - oscillator.damping * yd[1];
  return 0;
}

TEST(SmallVectorWithCvode, DampedOscillatorFollowsItsClosedForm) {
  SundialsContext context;
  const Oscillator oscillator;
  N_Vector y = NewSmallVector(2, context.get());
  N_VGetArrayPointer(y)[0] = 1.0;
  N_VGetArrayPointer(y)[1] = 0.0;
  void* cvode = CVodeCreate(CV_BDF, context.get());
  ASSERT_EQ(CVodeInit(cvode, OscillatorRhs, 0.0, y), CV_SUCCESS);
  ASSERT_EQ(CVodeSStolerances(cvode, 1e-10, 1e-12), CV_SUCCESS);
  ASSERT_EQ(CVodeSetUserData(cvode, const_cast<Oscillator*>(&oscillator)), CV_SUCCESS);
  SUNMatrix matrix = SUNDenseMatrix(2, 2, context.get());
  SUNLinearSolver solver = NewSmallDenseSolver(y, matrix, context.get());
  // no Jacobian function: CVODE's difference quotients write the matrix's columns through
  // N_VCloneEmpty and N_VSetArrayPointer
  ASSERT_EQ(CVodeSetLinearSolver(cvode, solver, matrix), CVLS_SUCCESS);

  // underdamped: y0 = exp(-c t / 2) (cos(w t) + c / (2 w) sin(w t)), w^2 = k - c^2 / 4
  const double decay = oscillator.damping / 2.0;
  const double w = std::sqrt(oscillator.stiffness - decay * decay);
  double worst = 0.0;
  for (int step = 1; step <= 20; ++step) {
    const double t_out = 0.5 * step;
    double t = 0.0;
    ASSERT_EQ(CVode(cvode, t_out, y, &t, CV_NORMAL), CV_SUCCESS);
    const double exact = std::exp(-decay * t) * (std::cos(w * t) + decay / w * std::sin(w * t));
    worst = std::max(worst, std::abs(N_VGetArrayPointer(y)[0] - exact));
  }
  // rtol 1e-10 bounds the local error of each of some thousand steps; their sum over ten
  // seconds stays well under 1e-7, while a wrong vector operation or solve is off by far more
  EXPECT_LT(worst, 1e-7);
  long setups = 0;
  CVodeGetNumLinSolvSetups(cvode, &setups);
  EXPECT_GT(setups, 0);  // the solver was used
  CVodeFree(&cvode);
  SUNLinSolFree(solver);
  SUNMatDestroy(matrix);
  N_VDestroy(y);
}

}  // namespace
}  // namespace musclesim
