#include "Choices.h"

#include "ClusterBounds.h"

namespace conescope {

namespace {

constexpr const char* kOtherConesWording = "The article's average cone needs \u03b1 = {average}, the narrowest (minimal) {minimal}. ";

constexpr std::array<ConeDescriptor, kConeMethodCount> kCones = {{
    {ConeMethod::Average, "average", "The article's cone: V1 is the mean normal, \u03b1 the angle to the farthest normal.",
     {1.00, 0.50, 0.10}, "V1 is the mean normal, as in the article; the narrowest cone (minimal) needs only \u03b1 = {minimal}. "},
    {ConeMethod::SeedSphere, "seed-sphere",
     "The article's note: V1 towards the centre of the smallest sphere around the normals' tips.", {0.25, 0.80, 0.95},
     kOtherConesWording},
    {ConeMethod::Minimal, "minimal", "The narrowest cone that holds every normal (the smallest cap on the Gauss sphere).",
     {0.35, 0.90, 0.35},
     "It is the narrowest cone that holds them; the article's average cone (V1 = the mean normal) needs \u03b1 = {average}. "},
    {ConeMethod::Meshopt, "meshopt", "meshoptimizer's cone (meshopt_computeClusterBounds).", {0.95, 0.35, 0.60},
     kOtherConesWording},
    {ConeMethod::Chosen, "chosen",
     "Per cluster, the cone of the other four (with its apex as far forward as the faces allow) whose octagon test culls "
     "the cluster from the most of 4,096 eyes on the standard orbit's sphere, 3 half-diagonals out. The default.",
     {0.70, 0.45, 1.00},
     "It is, of the offered cones, the one whose octagon culls this cluster from the most eyes; the narrowest (minimal) needs "
     "\u03b1 = {minimal}, the article's average {average}. "},
}};

// The record layouts behind each byte count are in docs/statistics-schema.md.
constexpr std::array<CullTestDescriptor, kCullTestCount> kTests = {{
    {CullTest::Oracle, "oracle", "Checks every face exactly (n\u00b7(e \u2212 q) < 0 at every corner). The ceiling, not a real test.",
     0, ""},
    // axis (3 floats), sin alpha; statistics add 12 per vertex it reads
    {CullTest::Vertices, "vertices",
     "The cone seen from behind along the view vector to every vertex of the cluster. Exact for the cone, but one check per vertex.",
     16, ""},
    {CullTest::Aabb, "aabb", "The article's box test: the cone seen from behind along the view vector to each of the 8 box corners.",
     40, ""},  // axis, sin alpha, box (6 floats)
    {CullTest::AabbFast, "aabb-fast",
     "The box test in the article's optimised form: squares instead of a square root per corner.", 40, ""},
    {CullTest::Sphere, "sphere",
     "The article's sphere test: v\u00b7V1 > cos(B \u2212 asin(r/d)) with v towards the sphere's centre. Never culls with the eye "
     "inside the sphere.",
     36, ""},  // axis, sin and cos alpha, centre, radius
    {CullTest::Apex, "apex", "meshoptimizer's test: v\u00b7V1 > sin \u03b1 with v from the eye to the apex.", 28,
     ""},  // apex, axis, sin alpha
    {CullTest::Octagon, "octagon",
     "The apex test with an eight-sided cone of normals: tighter where the normals spread more one way than the other. Culls when "
     "g\u00b7v > 0 for each of its eight edges g.",
     112, ""},  // apex, eight edges (27 floats) and a rounding slack
    {CullTest::MeshoptSphere, "meshopt-sphere",
     "meshoptimizer's sphere test: (c \u2212 e)\u00b7V1 > sin \u03b1 |c \u2212 e| + r.", 32, ""},  // centre, radius, axis, sin alpha
    {CullTest::OctagonCompact, "octagon-compact",
     "The octagon test on a 16-byte record (edges quantised, kept conservative): what an engine would store.", 16,
     "the octagon test on the 16-byte record: culled iff g.(apex - e) > 0 for every decoded edge g"},
    {CullTest::MeshoptApexF32, "meshopt-apex-f32",
     "meshoptimizer's own record in float, tested as a shader does: dot(normalize(apex \u2212 e), axis) \u2265 cutoff. Not made "
     "safe: its culls of a cluster with a visible face are counted as the record's false culls.",
     28, "meshoptimizer's apex test in float: culled iff dot(normalize(cone_apex - e), cone_axis) >= cone_cutoff"},
    {CullTest::MeshoptSphereS8, "meshopt-sphere-s8",
     "meshoptimizer's 8-bit cone with its bounding sphere, tested as niagara's task shader does. Not made safe: its false culls "
     "are counted.",
     20,  // center, radius, cone_axis_s8, cone_cutoff_s8
     "niagara's test on meshoptimizer's 8-bit cone: culled iff dot(c - e, a) >= k |c - e| + r, a = cone_axis_s8 / 127, "
     "k = cone_cutoff_s8 / 127"},
    {CullTest::CadsceneBoxS8, "cadscene-box-s8",
     "NVIDIA cadscene's record: an octahedral axis, an 8-bit angle and an 8-bit box, tested at the box's 8 corners. Not made "
     "safe: its false culls are counted.",
     9,  // box 6 x UNORM8, octahedral axis 2 x SNORM8, -sin angle SNORM8
     "cadscene's test: culled iff its 8-bit angle is negative and dot(N, normalize(e - k)) < angle at all 8 corners k of its "
     "8-bit box (N its octahedral axis)"},
}};

constexpr std::array<BuilderDescriptor, kBuilderCount> kBuilders = {{
    {Builder::Meshlet, "meshlet", "Grows clusters face by face under the vertex and triangle limits, preferring narrow cones."},
    {Builder::KMeans, "kmeans", "k-means on position and normal to a target count."},
    {Builder::Meshopt, "meshopt", "meshoptimizer's own meshlet builder (meshopt_buildMeshlets)."},
    {Builder::File, "file", "The clusters a file gives: the mesh's cluster_id array or a text file of one id per face."},
    {Builder::Optimized, "optimized",
     "Groups faces so that the expected share of culled triangles is as large as it can be, at meshoptimizer's cluster count "
     "(the default)."},
}};

// Each enum value 0 .. N-1 has exactly one row: a new value without a row (or a row twice) stops the build.
template <typename Row, size_t N, typename Key>
constexpr bool everyValueOnce(const std::array<Row, N>& rows, Key key) {
    for (size_t value = 0; value < N; ++value) {
        size_t found = 0;
        for (const Row& row : rows) found += size_t(key(row)) == value ? 1 : 0;
        if (found != 1) return false;
    }
    return true;
}
static_assert(everyValueOnce(kCones, [](const ConeDescriptor& row) { return row.method; }), "kCones: one row per ConeMethod");
static_assert(everyValueOnce(kTests, [](const CullTestDescriptor& row) { return row.test; }), "kTests: one row per CullTest");
static_assert(everyValueOnce(kBuilders, [](const BuilderDescriptor& row) { return row.builder; }), "kBuilders: one row per Builder");
// The counts above are the enums' sizes: a value past the last row fails here.
static_assert(size_t(ConeMethod::Chosen) + 1 == kConeMethodCount, "kConeMethodCount is ConeMethod's size");
static_assert(size_t(CullTest::OctagonCompact) + 1 == kCullTestCount, "kCullTestCount is CullTest's size");
static_assert(size_t(Builder::Optimized) + 1 == kBuilderCount, "kBuilderCount is Builder's size");

// The rows ordered by enum value, for lookups.
template <typename Row, size_t N, typename Key>
constexpr std::array<size_t, N> rowOfValue(const std::array<Row, N>& rows, Key key) {
    std::array<size_t, N> index{};
    for (size_t row = 0; row < N; ++row) index[size_t(key(rows[row]))] = row;
    return index;
}
constexpr auto kConeRow = rowOfValue(kCones, [](const ConeDescriptor& row) { return row.method; });
constexpr auto kTestRow = rowOfValue(kTests, [](const CullTestDescriptor& row) { return row.test; });
constexpr auto kBuilderRow = rowOfValue(kBuilders, [](const BuilderDescriptor& row) { return row.builder; });

}  // namespace

const std::array<ConeDescriptor, kConeMethodCount>& coneDescriptors() { return kCones; }
const std::array<CullTestDescriptor, kCullTestCount>& cullTestDescriptors() { return kTests; }
const std::array<BuilderDescriptor, kBuilderCount>& builderDescriptors() { return kBuilders; }

const ConeDescriptor& descriptor(ConeMethod method) { return kCones[kConeRow[size_t(method)]]; }
const CullTestDescriptor& descriptor(CullTest test) { return kTests[kTestRow[size_t(test)]]; }
const BuilderDescriptor& descriptor(Builder builder) { return kBuilders[kBuilderRow[size_t(builder)]]; }

}  // namespace conescope
