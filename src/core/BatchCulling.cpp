#include "BatchCulling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#define CONESCOPE_BATCH_X86 1
// GCC warns that the baseline-compiled templates pass __m256 values; they never do at run time,
// because flatten inlines every one of them into runAvx2 (no call is left in its code).
#pragma GCC diagnostic ignored "-Wpsabi"
#include <immintrin.h>
// clang refuses to pass __m256 through baseline-compiled templates even when they are inlined
// into a target("avx2") function, so a clang build (the sanitizer build) stops at SSE2 unless it
// targets AVX2 as a whole.
#if !defined(__clang__) || defined(__AVX2__)
#define CONESCOPE_BATCH_AVX2 1
#endif
#endif

// Why the float tests are conservative (u = 2^-24, M = the cluster's largest coordinate (its centre
// plus radius, its apex) + max |eye coordinate|, all
// vectors measured against the exact double data of ClusterBounds):
//  - storing the eye, a centre or an apex in float and subtracting moves the view vector v by at
//    most ~5.3 u M; the stored axis is off by at most sqrt(3) u per unit length;
//  - so the float dot product is at most v.V1 + 5.3 u M + 4.8 u |v|, and the float length is
//    within 3 u |v| + 6 u M of |v|;
//  - every test adds error = 16 u length + 64 u M to its threshold and compares strictly, and its
//    sin(alpha) carries kBatchSinMargin (> 9.3 u) for the rounding of the product with it;
//  - the octagon test compares v.g with that error for each unit edge g, stored in float as the
//    axis is: the same bound holds for each.
// Hence a float "cull" implies the exact inequality on the double bounds, which is what makes the
// double test conservative (Culling.h). The tests in tests/core/BatchCullingTests.cpp check the
// result against the per-face oracle.

namespace conescope {

namespace {

constexpr float kSlackRelative = float(kBatchRelativeSlack);
constexpr float kNeverCulledSin = 2.0f;  // above any |v.V1| / |v|: the comparison cannot pass

float roundUp(double value) {
    float f = float(value);
    if (double(f) < value) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

float roundDown(double value) {
    float f = float(value);
    if (double(f) > value) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

double maxAbs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// What every lane of one call shares: the eye in float and the eye's part of the absolute slack
// (each cluster adds its own part, ClusterBatch::slack).
struct EyeConstants {
    float x, y, z;
    float absoluteSlack;
};

EyeConstants eyeConstants(const glm::dvec3& eye) {
    return {float(eye.x), float(eye.y), float(eye.z), roundUp(kBatchAbsoluteSlack * maxAbs(eye))};
}

// Byte k of entry m is bit k of m: turns a SIMD comparison mask into 0/1 bytes with one store.
constexpr std::array<uint64_t, 256> makeBytesOfBits() {
    std::array<uint64_t, 256> table{};
    for (unsigned m = 0; m < 256; ++m)
        for (unsigned k = 0; k < 8; ++k)
            if (m & (1u << k)) table[m] |= uint64_t(1) << (8 * k);
    return table;
}
constexpr std::array<uint64_t, 256> kBytesOfBits = makeBytesOfBits();

// ---- Lanes: the few operations the kernels need, on 1 (scalar), 4 (SSE2) or 8 (AVX2) floats.

struct ScalarLanes {
    using F = float;
    using M = bool;
    static constexpr size_t width = 1;
    static F load(const float* p) { return *p; }
    static F broadcast(float x) { return x; }
    static F sqrt(F x) { return std::sqrt(x); }
    static M greater(F a, F b) { return a > b; }
    static M both(M a, M b) { return a && b; }
    static unsigned bits(M m) { return m ? 1u : 0u; }
};

#ifdef CONESCOPE_BATCH_X86
struct Sse2Float {
    __m128 v;
};
inline Sse2Float operator+(Sse2Float a, Sse2Float b) { return {_mm_add_ps(a.v, b.v)}; }
inline Sse2Float operator-(Sse2Float a, Sse2Float b) { return {_mm_sub_ps(a.v, b.v)}; }
inline Sse2Float operator*(Sse2Float a, Sse2Float b) { return {_mm_mul_ps(a.v, b.v)}; }
struct Sse2Lanes {
    using F = Sse2Float;
    using M = __m128;
    static constexpr size_t width = 4;
    static F load(const float* p) { return {_mm_loadu_ps(p)}; }
    static F broadcast(float x) { return {_mm_set1_ps(x)}; }
    static F sqrt(F x) { return {_mm_sqrt_ps(x.v)}; }
    static M greater(F a, F b) { return _mm_cmpgt_ps(a.v, b.v); }
    static M both(M a, M b) { return _mm_and_ps(a, b); }
    static unsigned bits(M m) { return unsigned(_mm_movemask_ps(m)); }
};

#ifdef CONESCOPE_BATCH_AVX2
// AVX2 code is compiled for that target only in these functions; the kernels below are plain
// templates that the flattened AVX2 entry points inline, so no AVX instruction runs on a CPU
// without it. No "fma" target: contracting a*b+c would change the rounding the scalar level has.
#define CONESCOPE_AVX2 __attribute__((target("avx2")))
struct Avx2Float {
    __m256 v;
};
CONESCOPE_AVX2 inline Avx2Float operator+(Avx2Float a, Avx2Float b) { return {_mm256_add_ps(a.v, b.v)}; }
CONESCOPE_AVX2 inline Avx2Float operator-(Avx2Float a, Avx2Float b) { return {_mm256_sub_ps(a.v, b.v)}; }
CONESCOPE_AVX2 inline Avx2Float operator*(Avx2Float a, Avx2Float b) { return {_mm256_mul_ps(a.v, b.v)}; }
struct Avx2Lanes {
    using F = Avx2Float;
    using M = __m256;
    static constexpr size_t width = 8;
    CONESCOPE_AVX2 static F load(const float* p) { return {_mm256_loadu_ps(p)}; }
    CONESCOPE_AVX2 static F broadcast(float x) { return {_mm256_set1_ps(x)}; }
    CONESCOPE_AVX2 static F sqrt(F x) { return {_mm256_sqrt_ps(x.v)}; }
    CONESCOPE_AVX2 static M greater(F a, F b) { return _mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ); }
    CONESCOPE_AVX2 static M both(M a, M b) { return _mm256_and_ps(a, b); }
    CONESCOPE_AVX2 static unsigned bits(M m) { return unsigned(_mm256_movemask_ps(m)); }
};
#endif
#endif

// Bit k of `bits` is the decision for cluster first + k.
template <class Lanes>
inline void storeBits(unsigned bits, uint8_t* culled, size_t first, size_t count) {
    if constexpr (Lanes::width == 1) {
        culled[first] = uint8_t(bits);
    } else {
        const uint64_t bytes = kBytesOfBits[bits];
        std::memcpy(culled + first, &bytes, std::min(Lanes::width, count - first));
    }
}

// ---- Kernels: one formula each, written once for every lane width.

// The eye and the slack constants in every lane, broadcast once per call.
template <class Lanes>
struct EyeLanes {
    typename Lanes::F x, y, z, slack, relative;
};

template <class Lanes>
inline EyeLanes<Lanes> broadcastEye(const EyeConstants& eye) {
    return {Lanes::broadcast(eye.x), Lanes::broadcast(eye.y), Lanes::broadcast(eye.z), Lanes::broadcast(eye.absoluteSlack),
            Lanes::broadcast(kSlackRelative)};
}

// What every test reads about the view vector v from the eye to a stored point (apex or sphere
// centre) of clusters i, i + 1, ...: v.V1, |v|, and the rounding slack for that length.
template <class Lanes>
struct View {
    typename Lanes::F along, length, error;
};

template <class Lanes>
inline View<Lanes> viewTo(const ClusterBatch& batch, const std::vector<float>& pointX, const std::vector<float>& pointY,
                          const std::vector<float>& pointZ, const EyeLanes<Lanes>& eye, size_t i) {
    using F = typename Lanes::F;
    const F vx = Lanes::load(&pointX[i]) - eye.x;
    const F vy = Lanes::load(&pointY[i]) - eye.y;
    const F vz = Lanes::load(&pointZ[i]) - eye.z;
    const F along = vx * Lanes::load(&batch.axisX[i]) + vy * Lanes::load(&batch.axisY[i]) + vz * Lanes::load(&batch.axisZ[i]);
    const F length = Lanes::sqrt(vx * vx + vy * vy + vz * vz);
    return {along, length, eye.relative * length + eye.slack + Lanes::load(&batch.slack[i])};
}

// Runs a test over all clusters, a lane group at a time: `test(view, i)` gives the mask of the
// clusters i, i + 1, ... it culls, from the view vector to the stored point (pointX, pointY, pointZ).
template <class Lanes, class Culls>
inline void cullEachGroup(const ClusterBatch& batch, const EyeConstants& constants, const std::vector<float>& pointX,
                          const std::vector<float>& pointY, const std::vector<float>& pointZ, uint8_t* culled, Culls test) {
    const EyeLanes<Lanes> eye = broadcastEye<Lanes>(constants);
    for (size_t i = 0; i < batch.count; i += Lanes::width)
        storeBits<Lanes>(Lanes::bits(test(viewTo<Lanes>(batch, pointX, pointY, pointZ, eye, i), i)), culled, i, batch.count);
}

template <class Lanes>
inline void apexKernel(const ClusterBatch& batch, const EyeConstants& constants, uint8_t* culled) {
    cullEachGroup<Lanes>(batch, constants, batch.apexX, batch.apexY, batch.apexZ, culled, [&](const View<Lanes>& v, size_t i) {
        return Lanes::greater(v.along, Lanes::load(&batch.sinHalfAngle[i]) * v.length + v.error);
    });
}

template <class Lanes>
inline void meshoptSphereKernel(const ClusterBatch& batch, const EyeConstants& constants, uint8_t* culled) {
    cullEachGroup<Lanes>(batch, constants, batch.centerX, batch.centerY, batch.centerZ, culled, [&](const View<Lanes>& v, size_t i) {
        return Lanes::greater(v.along, Lanes::load(&batch.sinHalfAngle[i]) * v.length + Lanes::load(&batch.radius[i]) + v.error);
    });
}

template <class Lanes>
inline void sphereKernel(const ClusterBatch& batch, const EyeConstants& constants, uint8_t* culled) {
    using F = typename Lanes::F;
    cullEachGroup<Lanes>(batch, constants, batch.centerX, batch.centerY, batch.centerZ, culled, [&](const View<Lanes>& v, size_t i) {
        // [low, high] holds the exact distance d, so the cone of views is judged with its worst case.
        const F high = v.length + v.error, low = v.length - v.error;
        const F r = Lanes::load(&batch.radius[i]);
        const auto outside = Lanes::greater(low * Lanes::load(&batch.cosHalfAngleDown[i]), r);
        // sin(alpha) sqrt(d^2 - r^2) + cos(alpha) r = d cos(B - asin(r/d)); NaN (d < r) never passes.
        const F tangent = Lanes::sqrt((high - r) * (high + r));
        const F threshold = Lanes::load(&batch.sinHalfAngle[i]) * tangent + Lanes::load(&batch.cosHalfAngleUp[i]) * r + v.error;
        return Lanes::both(Lanes::greater(v.along, threshold), outside);
    });
}

// Every edge of the octagon must see v from behind. All eight are tested, the masks joined in the
// lanes: some cluster of a group of eight is nearly always still in after the first edges.
template <class Lanes>
inline void octagonKernel(const ClusterBatch& batch, const EyeConstants& constants, uint8_t* culled) {
    using F = typename Lanes::F;
    const EyeLanes<Lanes> eye = broadcastEye<Lanes>(constants);
    for (size_t i = 0; i < batch.count; i += Lanes::width) {
        const float* block = &batch.octagonBlocks[i / 8 * ClusterBatch::kOctagonFields * 8 + i % 8];
        auto field = [&](size_t f) { return Lanes::load(block + 8 * f); };
        const F vx = field(0) - eye.x;
        const F vy = field(1) - eye.y;
        const F vz = field(2) - eye.z;
        const F error = eye.relative * Lanes::sqrt(vx * vx + vy * vy + vz * vz) + eye.slack + field(ClusterBatch::kOctagonFields - 1);
        auto edgeSeesBack = [&](size_t k) { return Lanes::greater(vx * field(3 + 3 * k) + vy * field(4 + 3 * k) + vz * field(5 + 3 * k), error); };
        auto all = Lanes::both(edgeSeesBack(0), edgeSeesBack(1));
        for (size_t k = 2; k < 8; ++k) all = Lanes::both(all, edgeSeesBack(k));
        storeBits<Lanes>(Lanes::bits(all), culled, i, batch.count);
    }
}

enum class Kernel { Sphere, Apex, MeshoptSphere, Octagon };

template <class Lanes>
inline void runKernel(Kernel kernel, const ClusterBatch& batch, const EyeConstants& eye, uint8_t* culled) {
    switch (kernel) {
        case Kernel::Sphere: sphereKernel<Lanes>(batch, eye, culled); break;
        case Kernel::Apex: apexKernel<Lanes>(batch, eye, culled); break;
        case Kernel::MeshoptSphere: meshoptSphereKernel<Lanes>(batch, eye, culled); break;
        case Kernel::Octagon: octagonKernel<Lanes>(batch, eye, culled); break;
    }
}

// Not inlined into the dispatcher, so each level is one function to profile and to read in a disassembly.
__attribute__((noinline)) void runScalar(Kernel kernel, const ClusterBatch& batch, const EyeConstants& eye,
                                         uint8_t* culled) {
    runKernel<ScalarLanes>(kernel, batch, eye, culled);
}

#ifdef CONESCOPE_BATCH_X86
__attribute__((noinline, flatten)) void runSse2(Kernel kernel, const ClusterBatch& batch, const EyeConstants& eye,
                                                uint8_t* culled) {
    runKernel<Sse2Lanes>(kernel, batch, eye, culled);
}

#ifdef CONESCOPE_BATCH_AVX2
__attribute__((noinline, flatten, target("avx2"))) void runAvx2(Kernel kernel, const ClusterBatch& batch,
                                                                const EyeConstants& eye, uint8_t* culled) {
    runKernel<Avx2Lanes>(kernel, batch, eye, culled);
}
#endif
#endif

void dispatch(Kernel kernel, const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled, SimdLevel level) {
    if (batch.count == 0) return;
    const EyeConstants constants = eyeConstants(eye);
    level = std::min(level, bestSimdLevel());
#ifdef CONESCOPE_BATCH_X86
#ifdef CONESCOPE_BATCH_AVX2
    if (level == SimdLevel::Avx2) return runAvx2(kernel, batch, constants, culled);
#endif
    if (level == SimdLevel::Sse2) return runSse2(kernel, batch, constants, culled);
#endif
    runScalar(kernel, batch, constants, culled);
}

}  // namespace

ClusterBatch makeClusterBatch(const ClusterBounds& bounds) {
    ClusterBatch batch;
    batch.count = bounds.count();
    const size_t padded = (batch.count + 7) / 8 * 8;
    for (std::vector<float>* column : {&batch.axisX, &batch.axisY, &batch.axisZ, &batch.centerX, &batch.centerY,
                                       &batch.centerZ, &batch.radius, &batch.apexX, &batch.apexY, &batch.apexZ,
                                       &batch.cosHalfAngleUp, &batch.cosHalfAngleDown})
        column->assign(padded, 0.0f);
    batch.octagonBlocks.assign(padded * ClusterBatch::kOctagonFields, 0.0f);
    batch.sinHalfAngle.assign(padded, kNeverCulledSin);
    batch.slack.assign(padded, 0.0f);
    for (size_t c = 0; c < batch.count; ++c) {
        const ConeOfNormals& cone = bounds.cones[c];
        const Sphere& sphere = bounds.spheres[c];
        const glm::dvec3& apex = bounds.apexes[c];
        batch.centerX[c] = float(sphere.center.x);
        batch.centerY[c] = float(sphere.center.y);
        batch.centerZ[c] = float(sphere.center.z);
        batch.radius[c] = roundUp(sphere.radius);
        batch.apexX[c] = float(apex.x);
        batch.apexY[c] = float(apex.y);
        batch.apexZ[c] = float(apex.z);
        // A cluster that cannot be culled keeps the zero axis and the threshold of 2.
        if (!cone.cullable || !(cone.cosHalfAngle > 0.0)) continue;
        // This cluster's part of the absolute slack: a cluster far from the origin (or an apex pushed
        // far by a face nearly edge-on to the axis) loosens its own test only.
        batch.slack[c] = roundUp(kBatchAbsoluteSlack * std::max(maxAbs(sphere.center) + sphere.radius, maxAbs(apex)));
        batch.axisX[c] = float(cone.axis.x);
        batch.axisY[c] = float(cone.axis.y);
        batch.axisZ[c] = float(cone.axis.z);
        // The sphere test reads B = asin(cos alpha), so its sine side must cover sqrt(1 - cos^2) too.
        const double cosine = std::min(cone.cosHalfAngle, 1.0);
        const double sine = std::max(cone.sinHalfAngle, std::sqrt(std::max(0.0, 1.0 - cosine * cosine)));
        batch.sinHalfAngle[c] = roundUp(sine + kBatchSinMargin);
        batch.cosHalfAngleUp[c] = roundUp(cosine + kBatchSinMargin);
        batch.cosHalfAngleDown[c] = std::max(0.0f, roundDown(cosine - kBatchSinMargin));
        const OctagonCone& octagon = bounds.octagons[c];
        if (!octagon.cullable) continue;  // zero edges: g.v = 0 never passes
        float* block = &batch.octagonBlocks[c / 8 * ClusterBatch::kOctagonFields * 8 + c % 8];
        const glm::dvec3* points[9] = {&apex};
        for (size_t k = 0; k < 8; ++k) points[k + 1] = &octagon.edges[k];
        for (size_t p = 0; p < 9; ++p)
            for (int axis = 0; axis < 3; ++axis) block[8 * (3 * p + axis)] = float((*points[p])[axis]);
        block[8 * (ClusterBatch::kOctagonFields - 1)] = batch.slack[c];
    }
    return batch;
}

SimdLevel bestSimdLevel() {
#ifdef CONESCOPE_BATCH_X86
#ifdef CONESCOPE_BATCH_AVX2
    static const SimdLevel best = __builtin_cpu_supports("avx2") ? SimdLevel::Avx2 : SimdLevel::Sse2;
#else
    static const SimdLevel best = SimdLevel::Sse2;
#endif
    return best;
#else
    return SimdLevel::Scalar;
#endif
}

const char* toString(SimdLevel level) {
    switch (level) {
        case SimdLevel::Scalar: return "scalar";
        case SimdLevel::Sse2: return "sse2";
        case SimdLevel::Avx2: return "avx2";
    }
    return "unknown";
}

void cullSphereBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled, SimdLevel level) {
    dispatch(Kernel::Sphere, batch, eye, culled, level);
}

void cullApexBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled, SimdLevel level) {
    dispatch(Kernel::Apex, batch, eye, culled, level);
}

void cullMeshoptSphereBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled, SimdLevel level) {
    dispatch(Kernel::MeshoptSphere, batch, eye, culled, level);
}

void cullOctagonBatch(const ClusterBatch& batch, const glm::dvec3& eye, uint8_t* culled, SimdLevel level) {
    dispatch(Kernel::Octagon, batch, eye, culled, level);
}

bool batchSupports(CullTest test) {
    return test == CullTest::Sphere || test == CullTest::Apex || test == CullTest::MeshoptSphere || test == CullTest::Octagon;
}

void cullBatch(const ClusterBatch& batch, const glm::dvec3& eye, CullTest test, uint8_t* culled, SimdLevel level) {
    switch (test) {
        case CullTest::Sphere: return cullSphereBatch(batch, eye, culled, level);
        case CullTest::Apex: return cullApexBatch(batch, eye, culled, level);
        case CullTest::MeshoptSphere: return cullMeshoptSphereBatch(batch, eye, culled, level);
        case CullTest::Octagon: return cullOctagonBatch(batch, eye, culled, level);
        default: break;
    }
    throw std::invalid_argument("no batched form of the " + toString(test) + " test");
}

std::vector<uint8_t> cullBatch(const ClusterBatch& batch, const glm::dvec3& eye, CullTest test, SimdLevel level) {
    std::vector<uint8_t> culled(batch.count);
    cullBatch(batch, eye, test, culled.data(), level);
    return culled;
}

}  // namespace conescope
