// The tests that read records of their own (EngineRecords.h), and what every test's record costs.
//
// Engine records, tested as the engine ships them and NOT made conservative: their culls of
// clusters holding a visible face are counted as false_culls, an engine bug for its user to see.
//   meshopt-apex-f32   meshopt_Bounds' apex, axis and cutoff, float apex test (meshopt/Meshopt.h)
//   meshopt-sphere-s8  meshopt_Bounds' sphere and 8-bit cone, niagara's test    (meshopt/Meshopt.h)
//   cadscene-box-s8    cadscene's 8-bit box and octahedral cone, its box test   (CadsceneCones.h)
// Conservative, like every other test:
//   octagon-compact    the octagon test on its 16-byte record                    (CompactOctagons.h)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ClusterBounds.h"
#include "CullTest.h"
#include "CullingInput.h"
#include "Views.h"

namespace conescope {

// What a record's test reads: the stages the bounds were made from, and the bounds (which hold the
// records, ClusterBounds::records). Culling.h's CullingInput carries the same.
// Whether the test reads a record of its own (one of the four above).
bool readsOwnRecord(CullTest test);
// Its rule in one line, for people (the picked cluster's page).
std::string ownRecordRule(CullTest test);

// Whether the test reproduces an engine's own record as shipped: exempt from the conservative
// rule, its false culls reported instead (the property test leaves exactly these out).
bool reproducesEngineRecord(CullTest test);

// Bytes per cluster of the record the test reads, as a renderer would store it (the layouts are in
// docs/statistics-schema.md, bytes_per_cluster); 0 for the oracle, which reads the faces themselves.
size_t recordBytes(CullTest test);

// The record's decision for one cluster (readsOwnRecord tests only).
bool ownRecordCulls(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test);

// Quantised records' float originals: meshopt-sphere-s8's the same test with meshopt_Bounds' float
// axis and cutoff, cadscene-box-s8's its float box, average axis and angle without the quantisation
// allowance, octagon-compact's the float octagon (the octagon test itself: measureCulling asks it).
// Their culls that the quantised record drew, in clusters whose every face faced away, are its
// quantisation loss.
bool hasFloatOriginal(CullTest test);
bool floatOriginalCulls(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test);

// How far the record passes its threshold (above 0 it culls), in units of a unit view's dot product.
double ownRecordMargin(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test);

// Share of view directions (eye at infinity) from which the record culls the cluster.
double ownRecordCullShare(const CullingInput& input, uint32_t cluster, CullTest test);


}  // namespace conescope
