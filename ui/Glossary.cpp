#include "Glossary.h"

#include <stdexcept>

#include <QCoreApplication>

#include "core/Choices.h"

namespace conescope {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("Glossary", text); }

// The general terms, in the order a lesson meets them; the cones and tests follow from their tables.
struct Term {
    const char* key;
    const char* term;
    const char* text;
};
const Term kTerms[] = {
    {"cluster", "Cluster",
     "A small group of neighbouring faces (a few dozen triangles) that is drawn, or skipped, as one piece. Culling a "
     "cluster saves all its triangles with one cheap test."},
    {"face normal", "Face normal",
     "The direction a face looks: at right angles to the face, pointing out of the surface. A face turns its back on "
     "the eye when the eye is behind it, n\u00b7(e \u2212 q) < 0 for the eye e and every corner q."},
    {"back-facing", "Back-facing face",
     "A face whose back the eye sees. A closed surface never shows its back faces, so they need not be drawn. A face "
     "seen exactly edge-on counts as visible."},
    {"gauss sphere", "Gauss sphere (Gauss map)",
     "The cluster's normals slid to start at one point: their tips lie on a sphere of radius 1. A flat patch puts them "
     "close together, a curved one spreads them out."},
    {"normal cone", "Normal cone (cone of normals)",
     "A cone around one direction, the axis V1, that holds every normal of a cluster. If the eye sees the whole cone "
     "from behind, it sees every face from behind, and the cluster can be skipped."},
    {"axis", "Cone axis V1", "The direction the cone of normals is centred on: roughly where the cluster's faces look."},
    {"alpha", "Half-angle \u03b1",
     "How far the cone opens: no normal is more than \u03b1 from V1 (cos \u03b1 = the smallest n\u00b7V1). A narrower "
     "cone (smaller \u03b1) can be culled from more places."},
    {"angle b", "Angle B",
     "The article's angle, 90\u00b0 \u2212 \u03b1: the cluster faces away from every view vector v within B of V1, "
     "that is when v\u00b7V1 > cos B = sin \u03b1."},
    {"view vector", "View vector v",
     "The unit vector from the eye towards the cluster (to the apex, the sphere's centre or a corner, as the test "
     "says). A test culls when v lies close enough to V1."},
    {"apex", "Apex",
     "A point behind the plane of every face of the cluster, on its cone axis. Seen from behind the cone, the apex "
     "stands for every point of the cluster, so one view vector is enough (the apex and octagon tests)."},
    {"bounding sphere", "Bounding sphere",
     "A sphere around the whole cluster (centre c, radius r). From distance d its points lie within asin(r/d) of the "
     "direction to c, which the sphere tests allow for."},
    {"bounding box", "Bounding box (AABB)",
     "The smallest box with sides along the axes that holds the cluster. The box tests check the view vector to each "
     "of its 8 corners."},
    {"margin", "Margin",
     "How far the test's tightest comparison is from its threshold: positive, the cluster is culled with that much to "
     "spare; negative, the test fell short by that much."},
    {"cull eye", "Cull eye",
     "The point the cull decisions are made from (magenta). The observer camera can look at the result from anywhere."},
    {"observer", "Observer camera", "The ordinary 3D view you turn with the mouse; it does not decide anything."},
    {"orbit", "Orbit",
     "A fixed set of eye positions spread evenly around the mesh (the golden-angle spiral), so every tool measures over "
     "the same views."},
    {"oracle", "Oracle",
     "The exact answer: a cluster may be skipped only when every one of its faces is back-facing. It checks each face, so "
     "it is too slow to ship, but it is the ceiling for any test."},
    {"cull fraction", "Cull fraction",
     "The share of all view directions (eyes far away) from which the test culls a cluster: (1 \u2212 sin \u03b1)/2 for "
     "a round cone, the area of its pyramid for the octagon test."},
    {"oracle fraction", "Oracle fraction",
     "The share of all view directions from which every face of a cluster faces away: the most any test could cull it "
     "from."},
    {"test loss", "Test loss",
     "Back faces drawn because the test was not sure: every face of their cluster faced away, yet the cluster was "
     "drawn. A narrower cone, a tighter bound or another test could save them."},
    {"partition loss", "Partition loss",
     "Back faces drawn because their cluster also holds a face the eye sees: no test may skip such a cluster. Only "
     "grouping the faces differently could save them."},
    {"efficiency", "Efficiency",
     "Triangles in culled clusters divided by all back-facing triangles: 100% would be as good as checking every "
     "triangle."},
    {"missed cull", "Missed cull", "A cluster whose every face faces away but which the test drew: its faces are the test's loss."},
    {"false cull", "False cull",
     "A cluster culled although a face of it could be seen. A correct test never makes one; ConeScope counts them to prove it."},
    {"builder", "Builder", "How the faces are grouped into clusters (the partition)."},
    {"degenerate face", "Degenerate face",
     "A face without area (its corners on one line): it has no normal, faces nowhere and never decides a cull."},
    {"visible face", "Visible face", "A face the cull eye may see: it faces the eye, or is seen edge-on."},
    {"lod level", "LOD level",
     "A level of a cluster LOD hierarchy: level 0 is the partition, each level above merges groups of neighbouring "
     "clusters, simplifies them to about half the triangles and splits them again. Coarse clusters are wider, so they "
     "cull less."},
    {"lod group", "LOD group",
     "Neighbouring clusters of one level simplified together; the level above makes its parents from them, and the "
     "cut draws either all of a group or its parents."},
    {"lod cut", "LOD cut",
     "The clusters an engine draws from the eye: per region the coarsest level whose simplification error, in pixels "
     "from the eye, is within the threshold (and whose group's is not)."},
    {"sub-group", "Sub-group (K cones per cluster)",
     "One of the K parts a cluster's faces are split into, each with its own cone of normals and the cluster's bounding "
     "sphere. A sub-group is skipped when its narrower cone faces away, so K cones cull more back faces than one, for a "
     "few more bytes per cluster."},
    {"not measured", "Not measured yet", "Nothing to show in this colouring yet: it appears once the eye (or A) is measured."},
};

}  // namespace

const std::vector<GlossaryEntry>& glossary() {
    static const std::vector<GlossaryEntry> entries = [] {
        std::vector<GlossaryEntry> list;
        for (const Term& term : kTerms) list.push_back({term.key, tr(term.term), tr(term.text)});
        for (const CullTestDescriptor& test : cullTestDescriptors())
            list.push_back({QStringLiteral("test ") + test.name, tr("Test: ") + test.name, tr(test.glossary)});
        for (const ConeDescriptor& cone : coneDescriptors())
            list.push_back({QStringLiteral("cone ") + cone.name, tr("Cone: ") + cone.name, tr(cone.glossary)});
        return list;
    }();
    return entries;
}

QString explain(const QString& key) {
    for (const GlossaryEntry& entry : glossary())
        if (entry.key == key) return entry.text;
    throw std::out_of_range("no glossary entry " + key.toStdString());
}

QString explain(CullTest test) { return explain(QStringLiteral("test ") + QString::fromStdString(toString(test))); }
QString explain(ConeMethod method) { return explain(QStringLiteral("cone ") + QString::fromStdString(toString(method))); }

QString explain(Builder builder) { return tr(descriptor(builder).explanation); }

QString explain(Effort effort) {
    switch (effort) {
        case Effort::Fast: return tr("Refines meshoptimizer's meshlets only: the quickest.");
        case Effort::Balanced: return tr("Refines them and adds a few annealing sweeps (the default).");
        case Effort::Best: return tr("Grows its own clusters and searches longest: the most culling, the slowest.");
    }
    return {};
}

QString explain(SphereMethod method) {
    switch (method) {
        case SphereMethod::Ritter: return tr("Ritter's sphere: quick, a little larger than it must be.");
        case SphereMethod::Minimal: return tr("The smallest sphere that holds the cluster (Welzl's algorithm).");
    }
    return {};
}

QString explain(Layer layer) {
    switch (layer) {
        case Layer::Faces: return tr("The mesh's faces, coloured as View > Colour faces by says.");
        case Layer::Borders: return tr("Lines where two clusters meet, so each cluster's outline shows.");
        case Layer::Cones: return explain(QStringLiteral("normal cone")) + tr(" Drawn from each cluster's centre.");
        case Layer::Normals: return explain(QStringLiteral("face normal"));
        case Layer::Boxes: return explain(QStringLiteral("bounding box"));
        case Layer::Spheres: return explain(QStringLiteral("bounding sphere"));
        case Layer::Eye: return explain(QStringLiteral("cull eye"));
        case Layer::Highlight: return tr("The picked cluster (click one): its outline, cone, box and sphere in yellow.");
        case Layer::Test: return tr("The picked cluster's test from the cull eye: the axis V1, the view vector v and the region "
                                    "of eye positions from which the test culls it (green).");
        case Layer::Legend: return tr("What the colours in the view mean.");
        case Layer::Lesson: return tr("What the lesson step shows of the picked cluster: its normals, the Gauss sphere, the cone, the bound.");
    }
    return {};
}

QString explain(FaceColoring coloring) {
    switch (coloring) {
        case FaceColoring::Cluster: return tr("Each cluster its own colour; neighbours never share one.");
        case FaceColoring::CullDecision: return tr("Grey: culled. Blue: drawn, a face may be seen. Orange: a missed cull, every face faced away.");
        case FaceColoring::FaceFacing: return tr("Each face by the oracle: front-facing or back-facing from the cull eye.");
        case FaceColoring::CullFraction: return explain(QStringLiteral("cull fraction"));
        case FaceColoring::OracleFraction: return explain(QStringLiteral("oracle fraction"));
        case FaceColoring::Loss: return tr("Each face from the cull eye: culled, lost to the test, lost to the partition, or visible.");
        case FaceColoring::Comparison: return tr("With A pinned: what only A culls, only B, both or neither.");
        case FaceColoring::LodLevel: return explain(QStringLiteral("lod level"));
        case FaceColoring::LodGroup: return explain(QStringLiteral("lod group"));
        case FaceColoring::LodCut: return explain(QStringLiteral("lod cut"));
        case FaceColoring::SubGroup:
            return tr("With K cones per cluster: each cluster's sub-groups in shades of its colour; grey: a sub-group the "
                      "K-cone test culls from the cull eye.");
    }
    return {};
}

QString explainLegendLabel(const std::string& label) {
    // Longest prefixes first: "culled by A only" before "culled".
    static const std::vector<std::pair<std::string, QString>> prefixes = {
        {"culled with front faces", "false cull"}, {"sub-group", "sub-group"}, {"culled back face", "back-facing"}, {"culled by", ""}, {"culled", "cluster"},
        {"missed cull", "missed cull"}, {"drawn by the LOD cut", "lod cut"}, {"LOD cut", "lod cut"}, {"LOD level", "lod level"},
        {"LOD groups", "lod group"}, {"drawn", "cluster"}, {"lost to the test", "test loss"},
        {"lost to the partition", "partition loss"}, {"cull fraction", "cull fraction"}, {"oracle fraction", "oracle fraction"},
        {"uncullable", "normal cone"}, {"face normals", "face normal"}, {"its face normals", "face normal"},
        {"normals from one point", "gauss sphere"}, {"cone axis", "axis"}, {"view vector", "view vector"}, {"cull eye", "cull eye"},
        {"eyes ", "cull eye"}, {"apex", "apex"}, {"bounding sphere", "bounding sphere"}, {"bounding box", "bounding box"},
        {"cluster AABBs", "bounding box"}, {"bounding spheres", "bounding sphere"}, {"normal cones", "normal cone"},
        {"front-facing", "face normal"}, {"back-facing", "back-facing"},
        {"degenerate", "degenerate face"}, {"visible", "visible face"}, {"point sees back", "view vector"},
        {"no ", "not measured"}, {"faces not classified", "not measured"}, {"unequal cluster counts", "efficiency"},
        {"clusters", "cluster"}, {"cluster", "cluster"}, {"picked cluster", "cluster"}};
    for (const ConeDescriptor& cone : coneDescriptors())  // "minimal cone, alpha 39.2 deg"
        if (label.rfind(std::string(cone.name) + " cone", 0) == 0) return explain(cone.method);
    for (const auto& [prefix, key] : prefixes) {
        if (label.rfind(prefix, 0) != 0) continue;
        if (key.isEmpty()) return explain(FaceColoring::Comparison);
        return explain(key);
    }
    return {};
}

QString glossaryHtml() {
    QString html = tr("<h2>Glossary</h2><p>The words ConeScope uses, in the order a lesson meets them.</p><dl>");
    for (const GlossaryEntry& entry : glossary())
        html += QStringLiteral("<dt><b>%1</b></dt><dd>%2</dd>").arg(entry.term.toHtmlEscaped(), entry.text.toHtmlEscaped());
    return html + QStringLiteral("</dl>");
}

QString aboutHtml() {
    return tr("<h2>ConeScope %1</h2>"
              "<p>Cluster back-face culling with normal cones, shown, measured and explained. A mesh is split into "
              "clusters of nearby faces; each gets a cone that holds its face normals and a bound; from the cull eye a "
              "cheap test decides whether the whole cluster faces away and can be skipped.</p>"
              "<p>The algorithm follows Jordan Isaak's article <i>Efficiently Culling Groups of Back-Facing Triangles</i> "
              "(the cone V1 and B, the bounding-box and bounding-sphere tests; called \"the article\" here) and meshoptimizer's cluster "
              "bounds (the apex test), compared with the exact per-face answer.</p>"
              "<p>Start a lesson with <b>L</b>; Help &gt; Glossary explains every term; Shift+F1 and a click on a "
              "control says what it does.</p>")
        .arg(QCoreApplication::applicationVersion().toHtmlEscaped());
}

}  // namespace conescope
