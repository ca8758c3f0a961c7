// The window's words for a newcomer, in one place: the glossary (Help > Glossary) and the texts the
// tooltips, What's This, legend tooltips and captions take from it, so a term is explained the same
// way wherever it appears.
#pragma once

#include <string>
#include <vector>

#include <QString>

#include "core/Settings.h"
#include "scene/SceneTypes.h"

namespace conescope {

struct GlossaryEntry {
    QString key;   // what the window looks it up by
    QString term;  // as the glossary lists it
    QString text;  // one to three plain sentences
};
const std::vector<GlossaryEntry>& glossary();
// The entry's text; throws std::out_of_range for a key the glossary does not have (a typo in the
// window's code, caught by the tests).
QString explain(const QString& key);

// The glossary as the Help page lists it, and the About page.
QString glossaryHtml();
QString aboutHtml();

// What a cull test, a cone method, a builder, a layer or a face colouring is, in words.
QString explain(CullTest test);
QString explain(ConeMethod method);
QString explain(Builder builder);
QString explain(Effort effort);
QString explain(SphereMethod method);
QString explain(Layer layer);
QString explain(FaceColoring coloring);

// What a legend entry means, from its label ("culled (8)", "lost to the test (114)", ...); empty
// when the label is not one the scene writes.
QString explainLegendLabel(const std::string& label);

}  // namespace conescope
