// A cluster LOD hierarchy of an icosphere, built once per test suite: building one per test would
// make the LOD suites slow, and every suite that walks a hierarchy builds it the same way.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "TestMeshes.h"
#include "core/lod/LodCut.h"

namespace conescope::testmesh {

// sphere_ is icosphere(Subdivisions) prepared without repair, hierarchy_ its hierarchy at the
// default settings.
template <int Subdivisions>
class IcosphereHierarchy : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        sphere_ = std::make_unique<PreparedMesh>(prepareMesh(std::make_shared<const Mesh>(icosphere(Subdivisions)), "test", false));
        hierarchy_ = std::make_unique<ClusterHierarchy>(buildClusterHierarchy(*sphere_, Settings{}));
    }
    static void TearDownTestSuite() { hierarchy_.reset(), sphere_.reset(); }
    static inline std::unique_ptr<PreparedMesh> sphere_;
    static inline std::unique_ptr<ClusterHierarchy> hierarchy_;
};

}  // namespace conescope::testmesh
