// The scene's data without looking at pixels: lookup tables, palette, glyph geometry, picking.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include "RenderTestSupport.h"
#include "core/Culling.h"
#include "scene/ClusterScene.h"
#include "scene/SceneGeometry.h"

namespace conescope {
namespace {

using rendertest::SceneInput;

ClusterScene makeScene(const SceneInput& input) {
    return ClusterScene(input.mesh, input.world, input.faces, input.partition, input.bounds);
}

glm::dvec3 pointOf(vtkPolyData* data, vtkIdType id) {
    double p[3];
    data->GetPoint(id, p);
    return {p[0], p[1], p[2]};
}

// Cells of a polydata grouped by their cluster_id cell value, each cell as its point ids.
std::map<int, std::vector<std::vector<vtkIdType>>> cellsByCluster(vtkPolyData* data) {
    std::map<int, std::vector<std::vector<vtkIdType>>> cells;
    auto* ids = vtkIntArray::SafeDownCast(data->GetCellData()->GetArray(clusterIdArrayName));
    EXPECT_NE(ids, nullptr);
    if (!ids) return cells;
    for (vtkIdType cell = 0; cell < data->GetNumberOfCells(); ++cell) {
        vtkIdType count = 0;
        const vtkIdType* points = nullptr;
        data->GetCellPoints(cell, count, points);
        cells[ids->GetValue(cell)].emplace_back(points, points + count);
    }
    return cells;
}

std::pair<uint32_t, uint32_t> undirectedEdge(vtkIdType a, vtkIdType b) {
    return {uint32_t(std::min(a, b)), uint32_t(std::max(a, b))};
}

Rgb tableColour(vtkLookupTable* table, int index) {
    double rgba[4];
    table->GetTableValue(index, rgba);
    return {rgba[0], rgba[1], rgba[2]};
}

// The colour a mapper's lookup table gives to cluster value `value` (through the range, as rendering does).
Rgb mappedColour(vtkLookupTable* table, int value) {
    const unsigned char* rgba = table->MapValue(double(value));
    return {rgba[0] / 255.0, rgba[1] / 255.0, rgba[2] / 255.0};
}

// Lookup tables store 8 bits per channel: half a step of rounding.
constexpr double tableTolerance = 0.5 / 255.0 + 1e-9;

void expectNear(const Rgb& a, const Rgb& b, double tolerance) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tolerance) << "component " << i;
}

class SceneStructure : public ::testing::Test {
protected:
    static void SetUpTestSuite() { torus_ = new SceneInput(rendertest::loadDataset("torus.off", 64)); }
    static void TearDownTestSuite() { delete torus_; }
    static SceneInput* torus_;
};
SceneInput* SceneStructure::torus_ = nullptr;

TEST_F(SceneStructure, LookupTablesHaveOneEntryPerClusterAndMapIdsToTheirEntry) {
    ClusterScene scene = makeScene(*torus_);
    const int clusters = int(torus_->partition.clusterCount);
    ASSERT_GT(clusters, 10);
    EXPECT_EQ(scene.clusterCount(), size_t(clusters));
    for (vtkLookupTable* table : {scene.paletteLookupTable(), scene.decisionLookupTable(), scene.visibleClustersLookupTable()})
        EXPECT_EQ(table->GetNumberOfTableValues(), clusters);
    // Cluster value c must pick table entry c, at both ends of the range too.
    for (int c = 0; c < clusters; ++c)
        expectNear(mappedColour(scene.paletteLookupTable(), c), scene.palette()[c], tableTolerance);

    auto* mapper = vtkMapper::SafeDownCast(scene.actor(Layer::Faces)->GetMapper());
    EXPECT_EQ(mapper->GetScalarMode(), VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
    EXPECT_STREQ(mapper->GetArrayName(), clusterIdArrayName);
    EXPECT_FALSE(mapper->GetInterpolateScalarsBeforeMapping());
    EXPECT_TRUE(mapper->GetUseLookupTableScalarRange());
    EXPECT_EQ(mapper->GetLookupTable(), scene.paletteLookupTable());

    auto* ids = vtkIntArray::SafeDownCast(scene.meshPolyData()->GetCellData()->GetArray(clusterIdArrayName));
    ASSERT_NE(ids, nullptr);
    ASSERT_EQ(ids->GetNumberOfTuples(), vtkIdType(torus_->mesh.faceCount()));
    for (size_t f = 0; f < torus_->mesh.faceCount(); ++f) EXPECT_EQ(ids->GetValue(vtkIdType(f)), int(torus_->partition.clusterOfFace[f]));
}

TEST_F(SceneStructure, DecisionsRewriteOnlyTheLookupTables) {
    ClusterScene scene = makeScene(*torus_);
    scene.setFaceColoring(FaceColoring::CullDecision);
    auto* mapper = vtkMapper::SafeDownCast(scene.actor(Layer::Faces)->GetMapper());
    EXPECT_EQ(mapper->GetLookupTable(), scene.decisionLookupTable());

    vtkPolyData* mesh = scene.meshPolyData();
    vtkDataArray* ids = mesh->GetCellData()->GetArray(clusterIdArrayName);
    const void* idsBefore = ids->GetVoidPointer(0);
    const vtkMTimeType idsTime = ids->GetMTime(), meshTime = mesh->GetMTime(), tableTime = scene.decisionLookupTable()->GetMTime();
    const vtkMTimeType visibleTime = scene.visibleClustersLookupTable()->GetMTime();

    // An eye on the +z axis of the torus: the cull test and the oracle decide per cluster.
    const Eye eye = Eye::perspective({0.3, 0.2, 3.0});
    const CullingInput cullInput{torus_->mesh, torus_->world, torus_->faces, torus_->bounds};
    const std::vector<uint8_t> culled = cullClusters(cullInput, eye, CullTest::Sphere);
    const std::vector<uint8_t> allBack = cullClusters(cullInput, eye, CullTest::Oracle);
    size_t culledCount = 0, missedCount = 0, drawnCount = 0;
    for (size_t c = 0; c < culled.size(); ++c) {
        EXPECT_FALSE(culled[c] && !allBack[c]) << "the sphere test culled a visible cluster " << c;
        (culled[c] ? culledCount : allBack[c] ? missedCount : drawnCount)++;
    }
    ASSERT_GT(culledCount, 0u);
    ASSERT_GT(missedCount, 0u);
    ASSERT_GT(drawnCount, 0u);
    scene.setClusterDecisions(culled, allBack);

    EXPECT_EQ(mesh->GetCellData()->GetArray(clusterIdArrayName), ids);
    EXPECT_EQ(ids->GetVoidPointer(0), idsBefore);
    EXPECT_EQ(ids->GetMTime(), idsTime);
    EXPECT_EQ(mesh->GetMTime(), meshTime);
    EXPECT_GT(scene.decisionLookupTable()->GetMTime(), tableTime);
    EXPECT_GT(scene.visibleClustersLookupTable()->GetMTime(), visibleTime);

    for (int c = 0; c < int(culled.size()); ++c) {
        const Rgb expected = culled[c] ? SceneColours::culled : allBack[c] ? SceneColours::missedCull : SceneColours::drawn;
        expectNear(tableColour(scene.decisionLookupTable(), c), expected, tableTolerance);
        double rgba[4];
        scene.visibleClustersLookupTable()->GetTableValue(c, rgba);
        EXPECT_EQ(rgba[3], culled[c] ? 0.0 : 1.0);
    }

    // The legend lists the three decisions with the table's colours.
    std::map<std::string, Rgb> entries;
    for (const LegendEntry& entry : scene.legend().entries()) entries[entry.label] = entry.colours.back();
    auto legendColour = [&](const std::string& prefix) {
        for (const auto& [label, colour] : entries)
            if (label.rfind(prefix, 0) == 0) return colour;
        ADD_FAILURE() << "no legend entry " << prefix;
        return Rgb{-1, -1, -1};
    };
    expectNear(legendColour("culled (" + std::to_string(culledCount) + ")"), SceneColours::culled, tableTolerance);
    expectNear(legendColour("missed cull"), SceneColours::missedCull, tableTolerance);
    expectNear(legendColour("drawn"), SceneColours::drawn, tableTolerance);

    scene.clearClusterDecisions();
    EXPECT_FALSE(scene.hasClusterDecisions());
    for (int c = 0; c < int(culled.size()); ++c) expectNear(tableColour(scene.decisionLookupTable(), c), SceneColours::undecided, tableTolerance);
    EXPECT_EQ(ids->GetMTime(), idsTime);
}

TEST_F(SceneStructure, WrongSizesAreRejected) {
    ClusterScene scene = makeScene(*torus_);
    const size_t k = scene.clusterCount();
    EXPECT_THROW(scene.setClusterDecisions(std::vector<uint8_t>(k - 1), std::vector<uint8_t>(k)), std::invalid_argument);
    EXPECT_THROW(scene.setClusterDecisions(std::vector<uint8_t>(k), std::vector<uint8_t>(k + 1)), std::invalid_argument);
    EXPECT_THROW(scene.setFaceFacing(std::vector<Facing>(3)), std::invalid_argument);
    EXPECT_THROW(scene.setHighlightedCluster(int(k)), std::out_of_range);
    EXPECT_THROW(scene.setHighlightedCluster(-2), std::out_of_range);
    Partition wrong = torus_->partition;
    wrong.clusterOfFace.pop_back();
    EXPECT_THROW(ClusterScene(torus_->mesh, torus_->world, torus_->faces, wrong, torus_->bounds), std::invalid_argument);
}

TEST_F(SceneStructure, FaceFacingWritesThePerFaceArrayAndSwitchesTheMapper) {
    ClusterScene scene = makeScene(*torus_);
    const std::vector<Facing> facing =
        classifyFaces(torus_->mesh, torus_->world, torus_->faces, Eye::perspective({0.0, 3.0, 1.0}));
    scene.setFaceFacing(facing);
    scene.setFaceColoring(FaceColoring::FaceFacing);
    auto* mapper = vtkMapper::SafeDownCast(scene.actor(Layer::Faces)->GetMapper());
    EXPECT_STREQ(mapper->GetArrayName(), facingArrayName);
    auto* array = vtkUnsignedCharArray::SafeDownCast(scene.meshPolyData()->GetCellData()->GetArray(facingArrayName));
    ASSERT_NE(array, nullptr);
    size_t back = 0;
    for (size_t f = 0; f < facing.size(); ++f) {
        EXPECT_EQ(array->GetValue(vtkIdType(f)), uint8_t(facing[f]));
        back += facing[f] == Facing::Back;
    }
    EXPECT_GT(back, 0u);
    auto* table = vtkLookupTable::SafeDownCast(mapper->GetLookupTable());
    expectNear(mappedColour(table, int(Facing::Front)), SceneColours::front, tableTolerance);
    expectNear(mappedColour(table, int(Facing::Back)), SceneColours::back, tableTolerance);
    expectNear(mappedColour(table, int(Facing::Degenerate)), SceneColours::degenerate, tableTolerance);
    // Glyphs keep the cluster palette in this mode; the faces go back to cluster ids afterwards.
    EXPECT_EQ(vtkMapper::SafeDownCast(scene.actor(Layer::Cones)->GetMapper())->GetLookupTable(), scene.paletteLookupTable());
    scene.setFaceColoring(FaceColoring::Cluster);
    EXPECT_STREQ(mapper->GetArrayName(), clusterIdArrayName);
    EXPECT_EQ(mapper->GetLookupTable(), scene.paletteLookupTable());
}

// Checks on a bundled mesh that clusters sharing a vertex never get the same colour class or colour.
void expectNeighboursDiffer(const SceneInput& input) {
    ClusterScene scene = makeScene(input);
    const ClusterAdjacency adjacency = clusterAdjacency(input.mesh, input.partition);
    const std::vector<uint32_t> classes = colourClasses(adjacency, uint32_t(baseHues().size()));
    std::set<std::pair<uint32_t, uint32_t>> expectedPairs;
    for (const auto& around : rendertest::clustersAroundVertices(input))
        for (uint32_t a : around)
            for (uint32_t b : around)
                if (a != b) expectedPairs.insert({a, b});
    std::set<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t c = 0; c + 1 < adjacency.starts.size(); ++c)
        for (uint32_t i = adjacency.starts[c]; i < adjacency.starts[c + 1]; ++i) pairs.insert({c, adjacency.neighbours[i]});
    EXPECT_EQ(pairs, expectedPairs);
    ASSERT_FALSE(pairs.empty());

    std::set<uint32_t> usedClasses;
    for (const auto& [a, b] : expectedPairs) {
        EXPECT_NE(classes[a], classes[b]) << "clusters " << a << " and " << b << " touch";
        EXPECT_NE(scene.palette()[a], scene.palette()[b]) << "clusters " << a << " and " << b << " touch";
        usedClasses.insert(classes[a]);
    }
    // Balanced use of the base hues, and the scene's palette table holds the palette.
    EXPECT_GE(usedClasses.size(), 4u);
    for (int c = 0; c < int(scene.clusterCount()); ++c) expectNear(tableColour(scene.paletteLookupTable(), c), scene.palette()[c], tableTolerance);
}

TEST_F(SceneStructure, NeighbouringClustersDifferInColourOnTheTorus) { expectNeighboursDiffer(*torus_); }

TEST(ScenePalette, NeighbouringClustersDifferInColourOnTheIcosphere) {
    expectNeighboursDiffer(rendertest::loadDataset("icosphere.off", 32));
}

TEST(ScenePalette, ClassesBeyondTheBaseHuesOpenOnlyWhenNeeded) {
    // A complete graph on 12 clusters needs 12 classes: all 10 hues and 2 extra ones, all distinct.
    ClusterAdjacency complete;
    complete.starts.push_back(0);
    for (uint32_t c = 0; c < 12; ++c) {
        for (uint32_t d = 0; d < 12; ++d)
            if (d != c) complete.neighbours.push_back(d);
        complete.starts.push_back(uint32_t(complete.neighbours.size()));
    }
    const std::vector<uint32_t> classes = colourClasses(complete, 10);
    EXPECT_EQ(std::set<uint32_t>(classes.begin(), classes.end()).size(), 12u);
    EXPECT_EQ(*std::max_element(classes.begin(), classes.end()), 11u);
    EXPECT_NE(colourOfClass(10), colourOfClass(11));
    for (uint32_t k = 0; k < 10; ++k) EXPECT_NE(colourOfClass(10), colourOfClass(k));
}

TEST_F(SceneStructure, ConeGlyphsHaveTheClusterConesHalfAngle) {
    ClusterScene scene = makeScene(*torus_);
    const auto cones = cellsByCluster(scene.conePolyData());
    size_t cullable = 0;
    for (size_t c = 0; c < torus_->bounds.count(); ++c) cullable += torus_->bounds.cones[c].cullable;
    ASSERT_GT(cullable, 0u);
    EXPECT_EQ(cones.size(), cullable);
    for (const auto& [cluster, triangles] : cones) {
        const ConeOfNormals& cone = torus_->bounds.cones[cluster];
        const Sphere& sphere = torus_->bounds.spheres[cluster];
        ASSERT_TRUE(cone.cullable);
        // The apex is the point every triangle shares; it sits at the sphere centre.
        std::map<vtkIdType, int> uses;
        for (const auto& triangle : triangles)
            for (vtkIdType p : triangle) uses[p]++;
        const auto apex = std::max_element(uses.begin(), uses.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
        EXPECT_EQ(uses[apex], int(triangles.size()));
        const glm::dvec3 apexPoint = pointOf(scene.conePolyData(), apex);
        EXPECT_LT(glm::distance(apexPoint, sphere.center), 1e-6 * (1.0 + sphere.radius));
        for (const auto& [point, count] : uses) {
            if (point == apex) continue;
            const glm::dvec3 side = pointOf(scene.conePolyData(), point) - apexPoint;
            const double angle = std::acos(std::clamp(glm::dot(glm::normalize(side), cone.axis), -1.0, 1.0));
            EXPECT_NEAR(angle, cone.halfAngle(), 1e-4) << "cluster " << cluster;
            EXPECT_NEAR(glm::length(side), sphere.radius, 1e-5 * (1.0 + sphere.radius));
        }
    }
}

TEST_F(SceneStructure, BoxLinesAreTheEdgesOfTheClusterBoxes) {
    ClusterScene scene = makeScene(*torus_);
    const auto boxes = cellsByCluster(scene.boxPolyData());
    ASSERT_EQ(boxes.size(), torus_->bounds.count());
    for (const auto& [cluster, lines] : boxes) {
        const Aabb& box = torus_->bounds.boxes[cluster];
        ASSERT_EQ(lines.size(), 12u);
        std::set<std::pair<std::array<int, 3>, std::array<int, 3>>> edges;
        for (const auto& line : lines) {
            ASSERT_EQ(line.size(), 2u);
            std::array<int, 3> ends[2];
            for (int e = 0; e < 2; ++e) {
                const glm::dvec3 p = pointOf(scene.boxPolyData(), line[e]);
                for (int axis = 0; axis < 3; ++axis) {
                    // Each coordinate is exactly the box's min or max on that axis.
                    const bool atMin = p[axis] == double(box.min[axis]), atMax = p[axis] == double(box.max[axis]);
                    EXPECT_TRUE(atMin || atMax) << "cluster " << cluster;
                    ends[e][axis] = atMax ? 1 : 0;
                }
            }
            int differing = 0;
            for (int axis = 0; axis < 3; ++axis) differing += ends[0][axis] != ends[1][axis];
            EXPECT_EQ(differing, 1);  // an edge, not a diagonal
            edges.insert(std::minmax(ends[0], ends[1]));
        }
        EXPECT_EQ(edges.size(), 12u);
    }
}

TEST_F(SceneStructure, SphereCirclesLieOnTheBoundingSpheres) {
    ClusterScene scene = makeScene(*torus_);
    const auto spheres = cellsByCluster(scene.spherePolyData());
    ASSERT_EQ(spheres.size(), torus_->bounds.count());
    for (const auto& [cluster, lines] : spheres) {
        const Sphere& sphere = torus_->bounds.spheres[cluster];
        for (const auto& line : lines)
            for (vtkIdType p : line)
                EXPECT_NEAR(glm::distance(pointOf(scene.spherePolyData(), p), sphere.center), sphere.radius, 1e-5 * sphere.radius);
    }
}

TEST_F(SceneStructure, BordersAreExactlyTheEdgesBetweenClustersAndOpenEdges) {
    // Brute force: the faces of every undirected edge.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edgeFaces;
    const Mesh& mesh = torus_->mesh;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            const uint32_t a = mesh.faceBegin(f)[k], b = mesh.faceBegin(f)[(k + 1) % mesh.faceSize(f)];
            edgeFaces[std::minmax(a, b)].push_back(f);
        }
    std::set<std::pair<uint32_t, uint32_t>> expected;
    for (const auto& [edge, faces] : edgeFaces) {
        bool mixed = faces.size() == 1;
        for (uint32_t f : faces) mixed |= torus_->partition.clusterOfFace[f] != torus_->partition.clusterOfFace[faces[0]];
        if (mixed) expected.insert(edge);
    }
    ClusterScene scene = makeScene(*torus_);
    vtkPolyData* borders = scene.borderPolyData();
    EXPECT_EQ(borders->GetPoints(), scene.meshPolyData()->GetPoints());  // shared, not copied
    std::set<std::pair<uint32_t, uint32_t>> found;
    for (const auto& [cluster, lines] : cellsByCluster(borders))
        for (const auto& line : lines) {
            const auto edge = undirectedEdge(line[0], line[1]);
            found.insert(edge);
            const auto& faces = edgeFaces[edge];
            EXPECT_TRUE(std::any_of(faces.begin(), faces.end(), [&](uint32_t f) { return int(torus_->partition.clusterOfFace[f]) == cluster; }));
        }
    EXPECT_FALSE(expected.empty());
    EXPECT_EQ(found, expected);
    EXPECT_EQ(size_t(borders->GetNumberOfCells()), expected.size());

    // An open mesh: one face alone has three open edges.
    Mesh triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.addFace({0, 1, 2});
    Partition one{{0}, 1};
    EXPECT_EQ(borderEdges(triangle, one).clusterIds.size(), 3u);
}

TEST_F(SceneStructure, ClusterOfCellMapsEveryPickableActorBackToItsCluster) {
    ClusterScene scene = makeScene(*torus_);
    const auto& clusterOfFace = torus_->partition.clusterOfFace;
    for (vtkIdType f = 0; f < vtkIdType(clusterOfFace.size()); f += 7)
        EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Faces), f), int(clusterOfFace[f]));
    auto visible = scene.makeVisibleClustersActor();
    EXPECT_EQ(scene.clusterOfCell(visible, 5), int(clusterOfFace[5]));

    // Cone cells carry their cluster; boxes are 12 lines per cluster in cluster order.
    vtkIdType cell = 0;
    for (vtkIdType c = 0; c < scene.conePolyData()->GetNumberOfCells(); ++c) {
        const int expected = vtkIntArray::SafeDownCast(scene.conePolyData()->GetCellData()->GetArray(clusterIdArrayName))->GetValue(c);
        EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Cones), c), expected);
        EXPECT_TRUE(torus_->bounds.cones[expected].cullable);
    }
    for (cell = 0; cell < vtkIdType(12 * scene.clusterCount()); ++cell)
        EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Boxes), cell), int(cell / 12));
    const vtkIdType sphereLines = scene.spherePolyData()->GetNumberOfCells() / vtkIdType(scene.clusterCount());
    for (cell = 0; cell < scene.spherePolyData()->GetNumberOfCells(); cell += 5)
        EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Spheres), cell), int(cell / sphereLines));

    // Normals: arrow cells map to the face under them (arrows are made when the layer is shown).
    scene.setLayerVisible(Layer::Normals, true);
    scene.actor(Layer::Normals)->GetMapper()->Update();
    auto* arrows = vtkPolyData::SafeDownCast(scene.actor(Layer::Normals)->GetMapper()->GetInputAsDataSet());
    ASSERT_NE(arrows, nullptr);
    const vtkIdType cellsPerArrow = arrows->GetNumberOfCells() / vtkIdType(clusterOfFace.size());
    ASSERT_GT(cellsPerArrow, 0);
    ASSERT_EQ(arrows->GetNumberOfCells(), cellsPerArrow * vtkIdType(clusterOfFace.size()));
    for (vtkIdType f = 0; f < vtkIdType(clusterOfFace.size()); f += 11)
        EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Normals), f * cellsPerArrow + cellsPerArrow / 2), int(clusterOfFace[f]));

    // Highlight actors answer with the picked cluster.
    scene.setHighlightedCluster(3);
    EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Highlight), 0), 3);

    // Not ours, out of range, or no actor: -1.
    auto stranger = vtkSmartPointer<vtkActor>::New();
    stranger->SetMapper(scene.actor(Layer::Faces)->GetMapper());
    EXPECT_EQ(scene.clusterOfCell(stranger, 0), -1);
    EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Eye), 0), -1);
    EXPECT_EQ(scene.clusterOfCell(nullptr, 0), -1);
    EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Faces), -1), -1);
    EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Faces), vtkIdType(clusterOfFace.size())), -1);
}

TEST_F(SceneStructure, HighlightOutlinesThePickedClusterOnly) {
    ClusterScene scene = makeScene(*torus_);
    const int cluster = 2;
    scene.setHighlightedCluster(cluster);
    EXPECT_EQ(scene.highlightedCluster(), cluster);
    EXPECT_TRUE(scene.actor(Layer::Highlight)->GetVisibility());
    auto* outline = vtkPolyData::SafeDownCast(scene.actor(Layer::Highlight)->GetMapper()->GetInputAsDataSet());
    ASSERT_NE(outline, nullptr);
    ASSERT_GT(outline->GetNumberOfCells(), 0);
    // Every outline edge belongs to exactly one face of the cluster.
    std::map<std::pair<uint32_t, uint32_t>, int> clusterEdgeUses;
    const Mesh& mesh = torus_->mesh;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        if (int(torus_->partition.clusterOfFace[f]) != cluster) continue;
        for (size_t k = 0; k < mesh.faceSize(f); ++k)
            clusterEdgeUses[std::minmax(mesh.faceBegin(f)[k], mesh.faceBegin(f)[(k + 1) % mesh.faceSize(f)])]++;
    }
    size_t expected = 0;
    for (const auto& [edge, uses] : clusterEdgeUses) expected += uses == 1;
    EXPECT_EQ(size_t(outline->GetNumberOfCells()), expected);
    for (vtkIdType c = 0; c < outline->GetNumberOfCells(); ++c) {
        vtkIdType count = 0;
        const vtkIdType* points = nullptr;
        outline->GetCellPoints(c, count, points);
        EXPECT_EQ(clusterEdgeUses[undirectedEdge(points[0], points[1])], 1);
    }
    scene.setHighlightedCluster(-1);
    EXPECT_FALSE(scene.actor(Layer::Highlight)->GetVisibility());
}

TEST_F(SceneStructure, TestDrawingShowsOnlyForAPickedClusterAndIsNotPicked) {
    ClusterScene scene = makeScene(*torus_);
    EXPECT_TRUE(scene.layerVisible(Layer::Test));
    EXPECT_FALSE(scene.actor(Layer::Test)->GetVisibility());  // nothing drawn yet
    const CullingInput input{torus_->mesh, torus_->world, torus_->faces, torus_->bounds};
    const Eye eye = Eye::perspective({0.5, -2.0, 1.5});
    scene.setTestDrawing(makeTestDrawing(input, 3, eye, CullTest::Aabb));
    EXPECT_TRUE(scene.actor(Layer::Test)->GetVisibility());
    EXPECT_EQ(scene.testDrawing().cluster, 3);
    EXPECT_EQ(scene.clusterOfCell(scene.actor(Layer::Test), 0), -1);
    // The box test's eight corners, coloured by verdict; the apex test's region as a surface.
    bool cornersDrawn = false;
    for (const LegendEntry& entry : scene.legend().entries()) cornersDrawn |= entry.label == "point sees back / may face";
    EXPECT_TRUE(cornersDrawn);
    scene.setTestDrawing(makeTestDrawing(input, 3, eye, CullTest::Apex));
    auto* region = vtkPolyData::SafeDownCast(scene.actor(Layer::Test)->GetMapper()->GetInputAsDataSet());
    ASSERT_NE(region, nullptr);
    EXPECT_GT(region->GetNumberOfCells(), 0);
    CullTestDrawing outside;
    outside.cluster = int(scene.clusterCount());
    EXPECT_THROW(scene.setTestDrawing(outside), std::out_of_range);
    scene.setTestDrawing({});
    EXPECT_FALSE(scene.actor(Layer::Test)->GetVisibility());
}

TEST_F(SceneStructure, LayersSwitchTheirActorsAndTheLegend) {
    ClusterScene scene = makeScene(*torus_);
    EXPECT_TRUE(scene.layerVisible(Layer::Faces));
    EXPECT_FALSE(scene.layerVisible(Layer::Normals));
    EXPECT_FALSE(scene.actor(Layer::Eye)->GetVisibility());  // no eye yet
    scene.setEye(Eye::perspective({0, 0, 3}), {0, 0, 0});
    EXPECT_TRUE(scene.actor(Layer::Eye)->GetVisibility());
    const size_t entriesBefore = scene.legend().entries().size();
    for (Layer layer : {Layer::Faces, Layer::Borders, Layer::Cones, Layer::Boxes, Layer::Spheres, Layer::Normals, Layer::Eye}) {
        const bool was = scene.actor(layer)->GetVisibility();
        scene.setLayerVisible(layer, !was);
        EXPECT_NE(bool(scene.actor(layer)->GetVisibility()), was) << toString(layer);
        EXPECT_NE(scene.legend().entries().size(), entriesBefore) << toString(layer);
        scene.setLayerVisible(layer, was);
        EXPECT_EQ(scene.legend().entries().size(), entriesBefore) << toString(layer);
    }
    scene.setLayerVisible(Layer::Legend, false);
    EXPECT_FALSE(scene.legend().drawn());
    EXPECT_FALSE(scene.legend().prop()->GetVisibility());
}

TEST_F(SceneStructure, EyeMarkerSitsAtThePerspectiveEyeAndOutsideTheMeshForDirections) {
    ClusterScene scene = makeScene(*torus_);
    const glm::dvec3 position(-1.6, 2.4, 1.5), target(0.2, 0.0, 0.0);
    scene.setEye(Eye::perspective(position), target);
    auto* marker = vtkPolyData::SafeDownCast(scene.actor(Layer::Eye)->GetMapper()->GetInputAsDataSet());
    ASSERT_NE(marker, nullptr);
    ASSERT_GT(marker->GetNumberOfPoints(), 0);
    // Every point is near the eye except the end of the line of sight, which is the target.
    double nearest = 1e30, farthest = 0.0;
    for (vtkIdType p = 0; p < marker->GetNumberOfPoints(); ++p) {
        nearest = std::min(nearest, glm::distance(pointOf(marker, p), target));
        farthest = std::max(farthest, glm::distance(pointOf(marker, p), position));
    }
    EXPECT_LT(nearest, 1e-6);
    EXPECT_NEAR(farthest, glm::distance(position, target), 1e-5);

    const std::array<double, 6> bounds = scene.meshBounds();
    const glm::dvec3 center(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
    const double radius = 0.5 * glm::distance(glm::dvec3(bounds[0], bounds[2], bounds[4]), glm::dvec3(bounds[1], bounds[3], bounds[5]));
    const Eye along = Eye::orthographicAlong({0.0, -1.0, -1.0});
    scene.setEye(along, center);
    marker = vtkPolyData::SafeDownCast(scene.actor(Layer::Eye)->GetMapper()->GetInputAsDataSet());
    ASSERT_GT(marker->GetNumberOfPoints(), 0);
    for (vtkIdType p = 0; p < marker->GetNumberOfPoints(); ++p) {
        const glm::dvec3 point = pointOf(marker, p);
        EXPECT_GT(glm::distance(point, center), radius);
        EXPECT_LT(glm::dot(point - center, along.direction), 0.0);  // on the side the eye looks from
    }
}

TEST_F(SceneStructure, EyeCameraLooksFromTheEye) {
    ClusterScene scene = makeScene(*torus_);
    auto camera = vtkSmartPointer<vtkCamera>::New();
    const glm::dvec3 position(0.5, 2.0, 2.5), target(0.0, 0.1, 0.0);
    scene.setEye(Eye::perspective(position), target);
    scene.applyEyeToCamera(camera);
    double p[3], f[3], range[2];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    camera->GetClippingRange(range);
    EXPECT_LT(glm::distance(glm::dvec3(p[0], p[1], p[2]), position), 1e-12);
    EXPECT_LT(glm::distance(glm::dvec3(f[0], f[1], f[2]), target), 1e-12);
    EXPECT_FALSE(camera->GetParallelProjection());
    EXPECT_GT(range[0], 0.0);
    EXPECT_LT(range[0], range[1]);

    const Eye along = Eye::orthographicAlong({1.0, 0.0, -1.0});
    scene.setEye(along, {0, 0, 0});
    scene.applyEyeToCamera(camera);
    EXPECT_TRUE(camera->GetParallelProjection());
    double direction[3];
    camera->GetDirectionOfProjection(direction);
    EXPECT_NEAR(glm::dot(glm::dvec3(direction[0], direction[1], direction[2]), along.direction), 1.0, 1e-12);
}

TEST_F(SceneStructure, NormalArrowsStartAtTheCentroidsWithAFractionOfTheMeanEdge) {
    ClusterScene scene = makeScene(*torus_);
    scene.setLayerVisible(Layer::Normals, true);
    scene.actor(Layer::Normals)->GetMapper()->Update();
    auto* arrows = vtkPolyData::SafeDownCast(scene.actor(Layer::Normals)->GetMapper()->GetInputAsDataSet());
    ASSERT_NE(arrows, nullptr);
    const size_t faceCount = torus_->mesh.faceCount();
    const vtkIdType pointsPerArrow = arrows->GetNumberOfPoints() / vtkIdType(faceCount);
    ASSERT_EQ(arrows->GetNumberOfPoints(), pointsPerArrow * vtkIdType(faceCount));
    const double length = 0.6 * scene.meanEdgeLength();
    EXPECT_GT(length, 0.0);
    for (size_t f = 0; f < faceCount; f += 13) {
        const glm::dvec3 centroid = torus_->faces.centroids[f];
        double farthest = 0.0, along = 0.0;
        for (vtkIdType p = vtkIdType(f) * pointsPerArrow; p < vtkIdType(f + 1) * pointsPerArrow; ++p) {
            const glm::dvec3 offset = pointOf(arrows, p) - centroid;
            farthest = std::max(farthest, glm::length(offset));
            along = std::max(along, glm::dot(offset, torus_->faces.normals[f]));
        }
        EXPECT_NEAR(farthest, length, 1e-4 * length) << "face " << f;
        EXPECT_NEAR(along, length, 1e-4 * length) << "face " << f;  // the tip lies along the normal
    }
}

}  // namespace
}  // namespace conescope
