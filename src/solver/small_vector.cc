#include "solver/small_vector.h"

#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <new>
#include <utility>

namespace musclesim {
namespace {

// Every vector points to its data; one made by NewSmallVector or N_VClone also holds them,
// right after this header in the same allocation (own_data), so N_VSetArrayPointer on it
// never leaks nor frees the caller's array.
struct SmallVectorContent {
  sunrealtype* data = nullptr;
  bool own_data = false;
};

template <int N>
struct OwningContent {
  SmallVectorContent header;
  sunrealtype storage[N];
};

inline sunrealtype* Data(N_Vector v) { return static_cast<SmallVectorContent*>(v->content)->data; }

// ---------------------------------------------------------------------------------------------
// construction, access and bookkeeping

N_Vector_ID GetVectorId(N_Vector) { return SUNDIALS_NVEC_CUSTOM; }

sunrealtype* GetArrayPointer(N_Vector v) { return Data(v); }

void SetArrayPointer(sunrealtype* data, N_Vector v) {
  static_cast<SmallVectorContent*>(v->content)->data = data;
}

void* GetCommunicator(N_Vector) { return nullptr; }

template <int N>
sunindextype GetLength(N_Vector) {
  return N;
}

template <int N>
void Space(N_Vector, sunindextype* real_words, sunindextype* integer_words) {
  // as NVECTOR_SERIAL counts: the data and the length
  *real_words = N;
  *integer_words = 1;
}

template <int N>
void Destroy(N_Vector v) {
  if (v == nullptr) return;
  auto* content = static_cast<SmallVectorContent*>(v->content);
  if (content != nullptr && content->own_data) {
    // the header is the first member of the standard-layout OwningContent
    delete reinterpret_cast<OwningContent<N>*>(content);
  } else {
    delete content;
  }
  v->content = nullptr;
  N_VFreeEmpty(v);
}

// A vector of length N with `ops` in `context`: holding its own data, or none.
template <int N>
N_Vector NewVector(SUNContext context, const _generic_N_Vector_Ops& ops, bool with_data);

template <int N>
N_Vector CloneEmpty(N_Vector w) {
  return NewVector<N>(w->sunctx, *w->ops, false);
}

template <int N>
N_Vector Clone(N_Vector w) {
  return NewVector<N>(w->sunctx, *w->ops, true);
}

// ---------------------------------------------------------------------------------------------
// standard operations (nvector_serial.c's results: the same formula for each case it singles
// out, so the same rounding)

template <int N>
void LinearSum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunrealtype* xd = Data(x);
  const sunrealtype* yd = Data(y);
  sunrealtype* zd = Data(z);
  // serial uses a(x + y) and a(x - y) for these; every other case of it equals a x + b y
  if (a == b) {
    for (int i = 0; i < N; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (a == -b) {
    for (int i = 0; i < N; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (int i = 0; i < N; ++i) zd[i] = a * xd[i] + b * yd[i];
  }
}

template <int N>
void Const(sunrealtype c, N_Vector z) {
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = c;
}

template <int N>
void Prod(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype* xd = Data(x);
  const sunrealtype* yd = Data(y);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = xd[i] * yd[i];
}

template <int N>
void Div(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype* xd = Data(x);
  const sunrealtype* yd = Data(y);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = xd[i] / yd[i];
}

template <int N>
void Scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunrealtype* xd = Data(x);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = c * xd[i];
}

template <int N>
void Abs(N_Vector x, N_Vector z) {
  const sunrealtype* xd = Data(x);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = std::abs(xd[i]);
}

template <int N>
void Inv(N_Vector x, N_Vector z) {
  const sunrealtype* xd = Data(x);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = 1.0 / xd[i];
}

template <int N>
void AddConst(N_Vector x, sunrealtype b, N_Vector z) {
  const sunrealtype* xd = Data(x);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = xd[i] + b;
}

template <int N>
sunrealtype DotProd(N_Vector x, N_Vector y) {
  const sunrealtype* xd = Data(x);
  const sunrealtype* yd = Data(y);
  sunrealtype sum = 0.0;
  for (int i = 0; i < N; ++i) sum += xd[i] * yd[i];
  return sum;
}

template <int N>
sunrealtype MaxNorm(N_Vector x) {
  const sunrealtype* xd = Data(x);
  sunrealtype max = 0.0;
  for (int i = 0; i < N; ++i) {
    if (std::abs(xd[i]) > max) max = std::abs(xd[i]);
  }
  return max;
}

template <int N>
sunrealtype WSqrSum(N_Vector x, N_Vector w) {
  const sunrealtype* xd = Data(x);
  const sunrealtype* wd = Data(w);
  sunrealtype sum = 0.0;
  for (int i = 0; i < N; ++i) {
    const sunrealtype product = xd[i] * wd[i];
    sum += product * product;
  }
  return sum;
}

template <int N>
sunrealtype WSqrSumMask(N_Vector x, N_Vector w, N_Vector id) {
  const sunrealtype* xd = Data(x);
  const sunrealtype* wd = Data(w);
  const sunrealtype* idd = Data(id);
  sunrealtype sum = 0.0;
  for (int i = 0; i < N; ++i) {
    if (idd[i] > 0.0) {
      const sunrealtype product = xd[i] * wd[i];
      sum += product * product;
    }
  }
  return sum;
}

template <int N>
sunrealtype WrmsNorm(N_Vector x, N_Vector w) {
  return std::sqrt(WSqrSum<N>(x, w) / N);
}

template <int N>
sunrealtype WrmsNormMask(N_Vector x, N_Vector w, N_Vector id) {
  return std::sqrt(WSqrSumMask<N>(x, w, id) / N);
}

template <int N>
sunrealtype Min(N_Vector x) {
  const sunrealtype* xd = Data(x);
  sunrealtype min = xd[0];
  for (int i = 1; i < N; ++i) {
    if (xd[i] < min) min = xd[i];
  }
  return min;
}

template <int N>
sunrealtype WL2Norm(N_Vector x, N_Vector w) {
  return std::sqrt(WSqrSum<N>(x, w));
}

template <int N>
sunrealtype L1Norm(N_Vector x) {
  const sunrealtype* xd = Data(x);
  sunrealtype sum = 0.0;
  for (int i = 0; i < N; ++i) sum += std::abs(xd[i]);
  return sum;
}

template <int N>
void Compare(sunrealtype c, N_Vector x, N_Vector z) {
  const sunrealtype* xd = Data(x);
  sunrealtype* zd = Data(z);
  for (int i = 0; i < N; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

template <int N>
sunbooleantype InvTest(N_Vector x, N_Vector z) {
  const sunrealtype* xd = Data(x);
  sunrealtype* zd = Data(z);
  // like serial: the other entries are still inverted, a zero's entry of z is left alone
  sunbooleantype no_zero_found = SUNTRUE;
  for (int i = 0; i < N; ++i) {
    if (xd[i] == 0.0) {
      no_zero_found = SUNFALSE;
    } else {
      zd[i] = 1.0 / xd[i];
    }
  }
  return no_zero_found;
}

template <int N>
sunbooleantype ConstrMask(N_Vector c, N_Vector x, N_Vector m) {
  const sunrealtype* cd = Data(c);
  const sunrealtype* xd = Data(x);
  sunrealtype* md = Data(m);
  // |c| = 2: x > 0 required (x < 0 for c = -2); |c| = 1: x >= 0 (x <= 0); c = 0: free
  bool all_met = true;
  for (int i = 0; i < N; ++i) {
    md[i] = 0.0;
    if (cd[i] == 0.0) continue;
    const bool violated = (std::abs(cd[i]) > 1.5 && xd[i] * cd[i] <= 0.0) ||
                          (std::abs(cd[i]) > 0.5 && xd[i] * cd[i] < 0.0);
    if (violated) {
      md[i] = 1.0;
      all_met = false;
    }
  }
  return all_met ? SUNTRUE : SUNFALSE;
}

template <int N>
sunrealtype MinQuotient(N_Vector num, N_Vector denom) {
  const sunrealtype* nd = Data(num);
  const sunrealtype* dd = Data(denom);
  // the first quotient starts the minimum, so an infinite one is returned as serial does
  bool none_yet = true;
  sunrealtype min = BIG_REAL;
  for (int i = 0; i < N; ++i) {
    if (dd[i] == 0.0) continue;
    const sunrealtype quotient = nd[i] / dd[i];
    if (none_yet) {
      min = quotient;
      none_yet = false;
    } else if (quotient < min) {
      min = quotient;
    }
  }
  return min;
}

// ---------------------------------------------------------------------------------------------
// fused operations; an entry at a time over all vectors, so z may be any of the inputs

template <int N>
int LinearCombination(int nvec, sunrealtype* c, N_Vector* x, N_Vector z) {
  if (nvec < 1) return -1;
  if (nvec == 1) {
    Scale<N>(c[0], x[0], z);
    return 0;
  }
  if (nvec == 2) {
    LinearSum<N>(c[0], x[0], c[1], x[1], z);
    return 0;
  }
  // serial sums c_0 x_0 + c_1 x_1 + ... in this order for each entry
  sunrealtype sum[N];
  const sunrealtype* x0 = Data(x[0]);
  for (int j = 0; j < N; ++j) sum[j] = c[0] * x0[j];
  for (int i = 1; i < nvec; ++i) {
    const sunrealtype* xi = Data(x[i]);
    for (int j = 0; j < N; ++j) sum[j] += c[i] * xi[j];
  }
  sunrealtype* zd = Data(z);
  for (int j = 0; j < N; ++j) zd[j] = sum[j];
  return 0;
}

template <int N>
int ScaleAddMulti(int nvec, sunrealtype* a, N_Vector x, N_Vector* y, N_Vector* z) {
  if (nvec < 1) return -1;
  if (nvec == 1) {
    LinearSum<N>(a[0], x, 1.0, y[0], z[0]);
    return 0;
  }
  const sunrealtype* xd = Data(x);
  for (int i = 0; i < nvec; ++i) {
    const sunrealtype* yd = Data(y[i]);
    sunrealtype* zd = Data(z[i]);
    for (int j = 0; j < N; ++j) zd[j] = a[i] * xd[j] + yd[j];
  }
  return 0;
}

template <int N>
int DotProdMulti(int nvec, N_Vector x, N_Vector* y, sunrealtype* dot_products) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) dot_products[i] = DotProd<N>(x, y[i]);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// vector-array operations

template <int N>
int LinearSumVectorArray(int nvec, sunrealtype a, N_Vector* x, sunrealtype b, N_Vector* y,
                         N_Vector* z) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) LinearSum<N>(a, x[i], b, y[i], z[i]);
  return 0;
}

template <int N>
int ScaleVectorArray(int nvec, sunrealtype* c, N_Vector* x, N_Vector* z) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) Scale<N>(c[i], x[i], z[i]);
  return 0;
}

template <int N>
int ConstVectorArray(int nvec, sunrealtype c, N_Vector* z) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) Const<N>(c, z[i]);
  return 0;
}

template <int N>
int WrmsNormVectorArray(int nvec, N_Vector* x, N_Vector* w, sunrealtype* norms) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) norms[i] = WrmsNorm<N>(x[i], w[i]);
  return 0;
}

template <int N>
int WrmsNormMaskVectorArray(int nvec, N_Vector* x, N_Vector* w, N_Vector id, sunrealtype* norms) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) norms[i] = WrmsNormMask<N>(x[i], w[i], id);
  return 0;
}

// z[j][i] = a[j] x[i] + y[j][i] for the nvec vectors i and the nsum sums j
template <int N>
int ScaleAddMultiVectorArray(int nvec, int nsum, sunrealtype* a, N_Vector* x, N_Vector** y,
                             N_Vector** z) {
  if (nvec < 1 || nsum < 1) return -1;
  for (int i = 0; i < nvec; ++i) {
    const sunrealtype* xd = Data(x[i]);
    for (int j = 0; j < nsum; ++j) {
      const sunrealtype* yd = Data(y[j][i]);
      sunrealtype* zd = Data(z[j][i]);
      for (int k = 0; k < N; ++k) zd[k] = a[j] * xd[k] + yd[k];
    }
  }
  return 0;
}

// z[i] = sum over j of c[j] x[j][i], for the nvec vectors i
template <int N>
int LinearCombinationVectorArray(int nvec, int nsum, sunrealtype* c, N_Vector** x, N_Vector* z) {
  if (nvec < 1 || nsum < 1) return -1;
  for (int i = 0; i < nvec; ++i) {
    if (nsum == 1) {
      Scale<N>(c[0], x[0][i], z[i]);
    } else if (nsum == 2) {
      LinearSum<N>(c[0], x[0][i], c[1], x[1][i], z[i]);
    } else {
      sunrealtype sum[N];
      const sunrealtype* x0 = Data(x[0][i]);
      for (int k = 0; k < N; ++k) sum[k] = c[0] * x0[k];
      for (int j = 1; j < nsum; ++j) {
        const sunrealtype* xj = Data(x[j][i]);
        for (int k = 0; k < N; ++k) sum[k] += c[j] * xj[k];
      }
      sunrealtype* zd = Data(z[i]);
      for (int k = 0; k < N; ++k) zd[k] = sum[k];
    }
  }
  return 0;
}

// ---------------------------------------------------------------------------------------------
// buffer operations (a vector's data packed as is)

template <int N>
int BufSize(N_Vector x, sunindextype* size) {
  if (x == nullptr) return -1;
  *size = N * static_cast<sunindextype>(sizeof(sunrealtype));
  return 0;
}

template <int N>
int BufPack(N_Vector x, void* buffer) {
  if (x == nullptr || buffer == nullptr) return -1;
  std::memcpy(buffer, Data(x), N * sizeof(sunrealtype));
  return 0;
}

template <int N>
int BufUnpack(N_Vector x, void* buffer) {
  if (x == nullptr || buffer == nullptr) return -1;
  std::memcpy(Data(x), buffer, N * sizeof(sunrealtype));
  return 0;
}

// ---------------------------------------------------------------------------------------------
// the operation tables, one per length

template <int N>
constexpr _generic_N_Vector_Ops MakeOps() {
  _generic_N_Vector_Ops ops{};
  ops.nvgetvectorid = GetVectorId;
  ops.nvclone = Clone<N>;
  ops.nvcloneempty = CloneEmpty<N>;
  ops.nvdestroy = Destroy<N>;
  ops.nvspace = Space<N>;
  ops.nvgetarraypointer = GetArrayPointer;
  ops.nvsetarraypointer = SetArrayPointer;
  ops.nvgetcommunicator = GetCommunicator;
  ops.nvgetlength = GetLength<N>;

  ops.nvlinearsum = LinearSum<N>;
  ops.nvconst = Const<N>;
  ops.nvprod = Prod<N>;
  ops.nvdiv = Div<N>;
  ops.nvscale = Scale<N>;
  ops.nvabs = Abs<N>;
  ops.nvinv = Inv<N>;
  ops.nvaddconst = AddConst<N>;
  ops.nvdotprod = DotProd<N>;
  ops.nvmaxnorm = MaxNorm<N>;
  ops.nvwrmsnorm = WrmsNorm<N>;
  ops.nvwrmsnormmask = WrmsNormMask<N>;
  ops.nvmin = Min<N>;
  ops.nvwl2norm = WL2Norm<N>;
  ops.nvl1norm = L1Norm<N>;
  ops.nvcompare = Compare<N>;
  ops.nvinvtest = InvTest<N>;
  ops.nvconstrmask = ConstrMask<N>;
  ops.nvminquotient = MinQuotient<N>;

  ops.nvlinearcombination = LinearCombination<N>;
  ops.nvscaleaddmulti = ScaleAddMulti<N>;
  ops.nvdotprodmulti = DotProdMulti<N>;

  ops.nvlinearsumvectorarray = LinearSumVectorArray<N>;
  ops.nvscalevectorarray = ScaleVectorArray<N>;
  ops.nvconstvectorarray = ConstVectorArray<N>;
  ops.nvwrmsnormvectorarray = WrmsNormVectorArray<N>;
  ops.nvwrmsnormmaskvectorarray = WrmsNormMaskVectorArray<N>;
  ops.nvscaleaddmultivectorarray = ScaleAddMultiVectorArray<N>;
  ops.nvlinearcombinationvectorarray = LinearCombinationVectorArray<N>;

  // the local reductions are the global ones: there is a single process
  ops.nvdotprodlocal = DotProd<N>;
  ops.nvmaxnormlocal = MaxNorm<N>;
  ops.nvminlocal = Min<N>;
  ops.nvl1normlocal = L1Norm<N>;
  ops.nvinvtestlocal = InvTest<N>;
  ops.nvconstrmasklocal = ConstrMask<N>;
  ops.nvminquotientlocal = MinQuotient<N>;
  ops.nvwsqrsumlocal = WSqrSum<N>;
  ops.nvwsqrsummasklocal = WSqrSumMask<N>;
  ops.nvdotprodmultilocal = DotProdMulti<N>;

  ops.nvbufsize = BufSize<N>;
  ops.nvbufpack = BufPack<N>;
  ops.nvbufunpack = BufUnpack<N>;
  return ops;
}

template <int N>
constexpr _generic_N_Vector_Ops kOps = MakeOps<N>();

template <int N>
N_Vector NewVector(SUNContext context, const _generic_N_Vector_Ops& ops, bool with_data) {
  N_Vector v = N_VNewEmpty(context);
  if (v == nullptr) return nullptr;
  // a copy: a clone keeps the operations its source had, as N_VCopyOps would give
  *v->ops = ops;
  SmallVectorContent* content = nullptr;
  if (with_data) {
    auto* owning = new (std::nothrow) OwningContent<N>;
    if (owning != nullptr) {
      owning->header.data = owning->storage;
      owning->header.own_data = true;
      content = &owning->header;
    }
  } else {
    content = new (std::nothrow) SmallVectorContent;
  }
  if (content == nullptr) {
    N_VFreeEmpty(v);
    return nullptr;
  }
  v->content = content;
  return v;
}

template <int N>
N_Vector NewOwningVector(SUNContext context) {
  return NewVector<N>(context, kOps<N>, true);
}

using Creator = N_Vector (*)(SUNContext);

// entry k makes a vector of length k + 1
template <int... I>
constexpr std::array<Creator, sizeof...(I)> MakeCreators(std::integer_sequence<int, I...>) {
  return {&NewOwningVector<I + 1>...};
}

constexpr std::array<Creator, kSmallVectorMaxLength> kCreators =
    MakeCreators(std::make_integer_sequence<int, kSmallVectorMaxLength>{});

}  // namespace

N_Vector NewSmallVector(int length, SUNContext context) {
  assert(length >= 1 && length <= kSmallVectorMaxLength);
  if (length < 1 || length > kSmallVectorMaxLength) return nullptr;
  return kCreators[length - 1](context);
}

bool IsSmallVector(N_Vector v) {
  return v != nullptr && v->ops != nullptr && v->ops->nvgetvectorid == GetVectorId;
}

}  // namespace musclesim
