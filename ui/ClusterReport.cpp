#include "ClusterReport.h"

#include <cmath>
#include <tuple>

#include <QStringList>

#include "core/RecordTests.h"
#include "core/Settings.h"

namespace conescope {

namespace {

QString number(double value) { return QString::number(value, 'g', 7); }
QString degrees(double value) { return QString::number(value, 'f', 3) + QStringLiteral("&deg;"); }

template <typename Vector>
QString vector3(const Vector& v) {
    return QStringLiteral("(%1, %2, %3)").arg(number(v.x), number(v.y), number(v.z));
}

QString yesNo(bool value) { return value ? QStringLiteral("yes") : QStringLiteral("no"); }

QString verdict(bool back) {
    return back ? QStringLiteral("<span style='color:#207020'>back</span>")
                : QStringLiteral("<span style='color:#b03020'>may face the eye</span>");
}

// A two-column table of (what, value) rows under a heading.
class Table {
public:
    explicit Table(const QString& heading) { html_ = QStringLiteral("<h3>%1</h3><table border='1' cellspacing='0' cellpadding='3'>").arg(heading); }
    Table& row(const QString& what, const QString& value) {
        html_ += QStringLiteral("<tr><td>%1</td><td>%2</td></tr>").arg(what, value);
        return *this;
    }
    QString html() const { return html_ + QStringLiteral("</table>"); }

private:
    QString html_;
};

QString clusterSection(const ClusterReportInput& input) {
    const ClusterBounds& bounds = *input.bounds;
    const uint32_t c = input.cluster;
    return Table(QStringLiteral("Cluster %1").arg(c))
        .row(QStringLiteral("faces"), QString::number(bounds.faces.starts[c + 1] - bounds.faces.starts[c]))
        .row(QStringLiteral("triangles"), QString::number(bounds.triangles[c]))
        .row(QStringLiteral("vertices"), QString::number(bounds.vertexStarts[c + 1] - bounds.vertexStarts[c]))
        .html();
}

QString coneSection(const ClusterReportInput& input) {
    const CullExplanation& why = input.explanation;
    Table table(QStringLiteral("Cone of normals (%1)").arg(QString::fromStdString(toString(input.bounds->coneMethod))));
    table.row(QStringLiteral("axis V1"), vector3(why.axis)).row(QStringLiteral("cullable"), yesNo(why.cullable));
    if (why.cullable) {
        table.row(QStringLiteral("half-angle &alpha;"), degrees(why.halfAngleDegrees))
            .row(QStringLiteral("min n&middot;V1 = cos &alpha;"), number(why.cosHalfAngle))
            .row(QStringLiteral("B = 90&deg; &minus; &alpha;"), degrees(why.angleBDegrees));
    } else {
        table.row(QStringLiteral("half-angle &alpha;"), QStringLiteral("no cone narrower than a hemisphere holds the normals"));
    }
    return table.html();
}

QString boundsSection(const ClusterReportInput& input) {
    const ClusterBounds& bounds = *input.bounds;
    const uint32_t c = input.cluster;
    return Table(QStringLiteral("Bounds (sphere: %1)").arg(QString::fromStdString(toString(bounds.sphereMethod))))
        .row(QStringLiteral("sphere centre c"), vector3(bounds.spheres[c].center))
        .row(QStringLiteral("sphere radius r"), number(bounds.spheres[c].radius))
        .row(QStringLiteral("AABB min"), vector3(bounds.boxes[c].min))
        .row(QStringLiteral("AABB max"), vector3(bounds.boxes[c].max))
        .row(QStringLiteral("apex"), vector3(bounds.apexes[c]))
        .html();
}

// Eight points or directions a test looks at, each with the value it compared and its verdict.
template <typename Row>
QString eightRowTable(const QString& what, const QString& position, const QString& value, Row row) {
    QString html = QStringLiteral("<table border='1' cellspacing='0' cellpadding='3'><tr><th>%1</th><th>%2</th><th>%3</th>"
                                  "<th>verdict</th></tr>")
                       .arg(what, position, value);
    for (int i = 0; i < 8; ++i) {
        const auto [point, compared, back] = row(i);
        html += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td></tr>").arg(i).arg(vector3(point), number(compared), verdict(back));
    }
    return html + QStringLiteral("</table>");
}

QString cornerTable(const CullExplanation& why) {
    return eightRowTable(QStringLiteral("corner k"), QStringLiteral("position"), QStringLiteral("v&middot;V1, v = (k &minus; e)/|k &minus; e|"),
                         [&](int i) { return std::tuple(why.corners[i], why.cornerDotAxis[i], why.cornerBack[i]); });
}

QString edgeTable(const CullExplanation& why) {
    return eightRowTable(QStringLiteral("edge k"), QStringLiteral("direction g"), QStringLiteral("g&middot;v"), [&](int i) {
        return std::tuple(why.octagonEdges[i], why.edgeDotView[i], why.edgeDotView[i] > why.threshold);
    });
}

// The octagon test's rows: what it compares (the orthographic and perspective forms differ only in v).
void octagonRows(Table& table, const CullExplanation& why, bool orthographic) {
    table.row(QStringLiteral("rule"), QStringLiteral("the normals fit in an eight-sided cone with edges g; culled iff g&middot;v &gt; 0 "
                                                     "for every edge, v = %1")
                                          .arg(orthographic ? QStringLiteral("d") : QStringLiteral("(apex &minus; e)/|apex &minus; e|: "
                                                                                                   "the apex lies behind every face plane")));
    if (!orthographic) table.row(QStringLiteral("apex"), vector3(why.apex));
    table.row(QStringLiteral("v"), vector3(why.view))
        .row(QStringLiteral("threshold (margin)"), number(why.threshold))
        .row(QStringLiteral("edges seeing the back"), QStringLiteral("%1 of 8").arg(why.edgesBack));
}

// The rows of the tests that compare v.V1 from a perspective eye; the corner table for the AABB tests.
QString perspectiveRows(Table& table, const CullExplanation& why, CullTest test) {
    switch (test) {
        case CullTest::Vertices:
            table.row(QStringLiteral("rule"), QStringLiteral("culled iff v&middot;V1 &gt; sin &alpha; for v = (q &minus; e)/|q &minus; e| "
                                                             "at every cluster vertex q"))
                .row(QStringLiteral("threshold sin &alpha; (+ margin)"), number(why.threshold))
                .row(QStringLiteral("vertices seeing the back"),
                     QStringLiteral("%1 of %2").arg(why.pointsBack).arg(why.pointsTested));
            break;
        case CullTest::Aabb:
        case CullTest::AabbFast:
            table.row(QStringLiteral("rule"),
                      test == CullTest::Aabb
                          ? QStringLiteral("culled iff v&middot;V1 &gt; sin &alpha; at all 8 AABB corners")
                          : QStringLiteral("culled iff (k &minus; e)&middot;V1 &gt; 0 and ((k &minus; e)&middot;V1)&sup2; &gt; "
                                           "sin&sup2; &alpha; |k &minus; e|&sup2; at all 8 corners k (no square root; "
                                           "the table shows the normalised form)"))
                .row(QStringLiteral("threshold sin &alpha; (+ margin)"), number(why.threshold))
                .row(QStringLiteral("corners seeing the back"),
                     QStringLiteral("%1 of %2").arg(why.pointsBack).arg(why.pointsTested));
            return cornerTable(why);
        case CullTest::Sphere:
            table.row(QStringLiteral("rule"), QStringLiteral("culled iff v&middot;V1 &gt; cos(B &minus; asin(r/d)), "
                                                             "v = (c &minus; e)/d, d = |c &minus; e|; never with the eye inside"))
                .row(QStringLiteral("d = |c &minus; e|"), number(why.distance))
                .row(QStringLiteral("r"), number(why.radius))
                .row(QStringLiteral("eye inside the sphere"), yesNo(why.eyeInsideSphere))
                .row(QStringLiteral("asin(r/d)"), why.eyeInsideSphere ? QStringLiteral("&mdash;") : degrees(why.sphereAngleDegrees))
                .row(QStringLiteral("B"), degrees(why.angleBDegrees))
                .row(QStringLiteral("v"), vector3(why.view))
                .row(QStringLiteral("v&middot;V1"), number(why.viewDotAxis))
                .row(QStringLiteral("threshold cos(B &minus; asin(r/d)) (+ margin)"), number(why.threshold));
            break;
        case CullTest::Apex:
            table.row(QStringLiteral("rule"), QStringLiteral("culled iff v&middot;V1 &gt; sin &alpha; for v = (apex &minus; e)/|apex &minus; e|: "
                                                             "the apex lies behind every face plane"))
                .row(QStringLiteral("apex"), vector3(why.apex))
                .row(QStringLiteral("v"), vector3(why.view))
                .row(QStringLiteral("v&middot;V1"), number(why.viewDotAxis))
                .row(QStringLiteral("threshold sin &alpha; (+ margin)"), number(why.threshold));
            break;
        case CullTest::MeshoptSphere:
            table.row(QStringLiteral("rule"), QStringLiteral("culled iff (c &minus; e)&middot;V1 &gt; sin &alpha; |c &minus; e| + r, "
                                                             "i.e. d (v&middot;V1) &gt; d sin &alpha; + r"))
                .row(QStringLiteral("d = |c &minus; e|"), number(why.distance))
                .row(QStringLiteral("r"), number(why.radius))
                .row(QStringLiteral("v = (c &minus; e)/d"), vector3(why.view))
                .row(QStringLiteral("v&middot;V1"), number(why.viewDotAxis))
                .row(QStringLiteral("sin &alpha; (+ margin)"), number(why.threshold));
            break;
        default: break;  // the oracle, the octagon and the records of their own are above
    }
    return QString();
}

// The steps of the chosen test with the numbers it compared.
QString testSection(const ClusterReportInput& input) {
    const CullExplanation& why = input.explanation;
    const Eye& eye = input.eye;
    const QString testName = QString::fromStdString(toString(input.test));
    Table table(QStringLiteral("Test &laquo;%1&raquo; from the eye").arg(testName));
    if (eye.orthographic)
        table.row(QStringLiteral("eye"), QStringLiteral("orthographic, looking along d = %1").arg(vector3(eye.direction)));
    else
        table.row(QStringLiteral("eye e"), vector3(eye.position));
    QString steps;
    if (input.test == CullTest::Oracle) {
        table.row(QStringLiteral("rule"), QStringLiteral("culled iff every face is back-facing: n&middot;(e &minus; q) &lt; 0 "
                                                         "at every vertex q (exact, per face)"));
    } else if (readsOwnRecord(input.test)) {
        table.row(QStringLiteral("rule"), QString::fromStdString(ownRecordRule(input.test)))
            .row(QStringLiteral("record"), QStringLiteral("%1 bytes a cluster%2")
                                               .arg(recordBytes(input.test))
                                               .arg(reproducesEngineRecord(input.test) ? QStringLiteral(", as the engine ships it (not conservative)")
                                                                                       : QString()));
    } else if (input.test == CullTest::Octagon) {
        octagonRows(table, why, eye.orthographic);
        steps = edgeTable(why);
    } else if (eye.orthographic) {
        table.row(QStringLiteral("rule"), QStringLiteral("from infinitely far every view vector is d: culled iff d&middot;V1 &gt; sin &alpha;"))
            .row(QStringLiteral("d&middot;V1"), number(why.viewDotAxis))
            .row(QStringLiteral("threshold sin &alpha; (+ margin)"), number(why.threshold));
    } else {
        steps = perspectiveRows(table, why, input.test);
    }
    if (!std::isnan(why.margin))
        table.row(input.test == CullTest::Octagon ? QStringLiteral("margin (tightest g&middot;v &minus; threshold)")
                                                  : QStringLiteral("margin (tightest v&middot;V1 &minus; threshold)"),
                  why.margin > 0.0 ? QStringLiteral("passes by %1").arg(number(why.margin))
                                   : QStringLiteral("<b>short by %1</b>").arg(number(-why.margin)));
    table.row(QStringLiteral("<b>decision</b>"), why.culled ? QStringLiteral("<b>culled</b>") : QStringLiteral("<b>drawn</b>"));
    if (why.culled && why.frontFaces > 0)
        table.row(QStringLiteral("<b>false cull</b>"), QStringLiteral("<b>%1 visible faces culled: the record culls too much here</b>").arg(why.frontFaces));
    if (why.culled != why.exactCulled)
        table.row(QStringLiteral("float kernel"), QStringLiteral("drawn: the exact test would cull it, but it lies within the batched "
                                                                 "kernel's rounding slack of the threshold"));
    return table.html() + steps;
}

// What the exact per-face classification says, and whether the decision was right.
QString truthSection(const CullExplanation& why) {
    QString outcome;
    if (why.culled && why.frontFaces > 0)
        outcome = QStringLiteral("<span style='color:#d00000'><b>false cull</b>: a front-facing face was culled</span>");
    else if (why.culled)
        outcome = QStringLiteral("correct cull: every face faces away");
    else if (why.frontFaces == 0 && why.backFaces > 0)
        outcome = QStringLiteral("<span style='color:#c06000'>missed cull</span>: every face faces away, the test was not sure");
    else
        outcome = QStringLiteral("correctly drawn: some face may be seen");
    return Table(QStringLiteral("Per-face truth (oracle)"))
        .row(QStringLiteral("front-facing faces"), QString::number(why.frontFaces))
        .row(QStringLiteral("back-facing faces"), QString::number(why.backFaces))
        .row(QStringLiteral("degenerate faces"), QString::number(why.degenerateFaces))
        .row(QStringLiteral("outcome"), outcome)
        .html();
}

}  // namespace

QString clusterReportHtml(const ClusterReportInput& input, const QString& appendix) {
    if (!input.bounds || input.cluster >= input.bounds->count()) return emptyClusterReportHtml();
    QStringList parts;
    parts << clusterSection(input) << coneSection(input) << boundsSection(input) << testSection(input)
          << truthSection(input.explanation) << appendix;
    return QStringLiteral("<html><body>") + parts.join(QString()) + QStringLiteral("</body></html>");
}

QString pinnedClusterHtml(const ClusterReportInput& a) {
    const CullExplanation& why = a.explanation;
    const ClusterBounds& bounds = *a.bounds;
    Table table(QStringLiteral("Under A (pinned): cluster %1").arg(a.cluster));
    table.row(QStringLiteral("triangles"), QString::number(bounds.triangles[a.cluster]))
        .row(QStringLiteral("cone / test"), QStringLiteral("%1 / %2").arg(QString::fromStdString(toString(bounds.coneMethod)),
                                                                          QString::fromStdString(toString(a.test))))
        .row(QStringLiteral("half-angle &alpha;"), why.cullable ? degrees(why.halfAngleDegrees) : QStringLiteral("no cone"));
    if (!std::isnan(why.margin))
        table.row(QStringLiteral("margin"), why.margin > 0.0 ? QStringLiteral("passes by %1").arg(number(why.margin))
                                                             : QStringLiteral("short by %1").arg(number(-why.margin)));
    table.row(QStringLiteral("<b>decision</b>"), why.culled ? QStringLiteral("<b>culled</b>") : QStringLiteral("<b>drawn</b>"));
    if (why.culled && why.frontFaces > 0)
        table.row(QStringLiteral("<b>false cull</b>"), QStringLiteral("<b>%1 visible faces culled: the record culls too much here</b>").arg(why.frontFaces));
    return table.html();
}

QString subGroupsHtml(const std::vector<SubGroupVerdict>& verdicts) {
    QString html = QStringLiteral("<h3>%1 cones: the cluster's sub-groups from the eye</h3>"
                                  "<table border='1' cellspacing='0' cellpadding='3'><tr><th>sub-group</th><th>triangles</th>"
                                  "<th>half-angle &alpha;</th><th>verdict</th><th>every face faces away</th></tr>")
                       .arg(verdicts.size());
    for (size_t i = 0; i < verdicts.size(); ++i) {
        const SubGroupVerdict& v = verdicts[i];
        const QString verdict = v.faces == 0 ? QStringLiteral("empty") : v.culled ? QStringLiteral("<b>culled</b>") : QStringLiteral("drawn");
        html += QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td><td>%4</td><td>%5</td></tr>")
                    .arg(i + 1)
                    .arg(v.triangles)
                    .arg(v.cullable ? degrees(v.halfAngleDegrees) : QStringLiteral("no cone"), verdict,
                         v.faces == 0 ? QStringLiteral("-") : v.allBackFacing ? QStringLiteral("yes") : QStringLiteral("no"));
    }
    return html + QStringLiteral("</table>");
}

QString emptyClusterReportHtml() {
    return QStringLiteral("<html><body><p>Click a cluster in the view (without dragging) to see its cone, its bounds "
                          "and every number the cull test compares for the current eye.</p></body></html>");
}

}  // namespace conescope
