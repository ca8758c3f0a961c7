// One visual layer of a ClusterScene, in the manner of polyscope's quantities: it owns its actors,
// builds them from the scene's shared data, shows and hides them, recolours them, says what its colours
// mean in the legend and maps a picked cell of its actors back to a cluster. Also the small VTK pieces
// every layer builds its actors from.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include "scene/SceneData.h"
#include "scene/SceneTypes.h"

class vtkActor;
class vtkLookupTable;
class vtkMapper;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkProp;

namespace conescope {

// One line of the legend: a label and its colours (more than one: "a colour per cluster"). With a
// scale the colours run evenly from its first value to its second: a colour bar with both written.
struct LegendEntry {
    LegendEntry(std::string label, std::vector<Rgb> colours, std::optional<std::array<double, 2>> scale = std::nullopt)
        : label(std::move(label)), colours(std::move(colours)), scale(scale) {}
    std::string label;
    std::vector<Rgb> colours;
    std::optional<std::array<double, 2>> scale;
    bool operator==(const LegendEntry& other) const {
        return label == other.label && colours == other.colours && scale == other.scale;
    }
};

class SceneLayer {
public:
    explicit SceneLayer(const SceneData& data) : data_(data) {}
    virtual ~SceneLayer() = default;

    // The layer's actors in drawing order; the first is the layer's main actor (ClusterScene::actor).
    virtual std::vector<vtkActor*> actors() const = 0;
    // 2D props drawn over the picture (labels), shown and hidden with the actors; not pickable.
    virtual std::vector<vtkProp*> overlays() const { return {}; }
    // Whether there is anything to draw yet (an eye, a picked cluster); the actors show only then.
    virtual bool hasContent() const { return true; }
    // Follows the face colouring; most layers keep their colours.
    virtual void recolour(FaceColoring) {}
    // Appends what the layer's colours mean; asked only while the layer is visible and has content.
    virtual void addLegendEntries(FaceColoring coloring, std::vector<LegendEntry>& entries) const = 0;
    // The cluster of cell cellId of one of this layer's actors, -1 if the id is out of range.
    virtual int clusterOfCell(vtkActor* actor, vtkIdType cellId) const;

    void setVisible(bool visible);
    bool visible() const { return visible_; }
    bool owns(vtkActor* actor) const;

protected:
    // Shows every actor while the layer is visible and has content; call after the content changes.
    void applyVisibility();

    const SceneData& data_;

private:
    bool visible_ = false;
};

// The cluster_id of a cell of the actor's input: the cell array, or for glyphs made by vtkGlyph3D the
// point array at the cell's first point; -1 if there is none or cellId is out of range.
int clusterIdOfCell(vtkActor* actor, vtkIdType cellId);

// A mapper that colours cells through `table` by an int cell array, without touching the array.
vtkSmartPointer<vtkPolyDataMapper> cellArrayMapper(vtkPolyData* input, const char* arrayName, vtkLookupTable* table);
vtkSmartPointer<vtkPolyDataMapper> plainMapper(vtkPolyData* input);
vtkSmartPointer<vtkActor> actorFor(vtkMapper* mapper);
// Unlit lines of the given width.
vtkSmartPointer<vtkActor> lineActor(vtkMapper* mapper, double width);
void setColour(vtkActor* actor, const Rgb& colour);
vtkSmartPointer<vtkPolyData> emptyPolyData();
// Points as vertex cells (each position times `scale`), and an actor drawing them as round dots.
vtkSmartPointer<vtkPolyData> pointPolyData(const std::vector<glm::dvec3>& positions, double scale = 1.0);
vtkSmartPointer<vtkActor> pointsActor(const Rgb& colour, double size);
// Replaces the input of the actor's mapper (the eye marker, the picked cluster's geometry).
void setInput(vtkActor* actor, vtkPolyData* data);

// " (n)": the count after a legend label.
std::string countLabel(size_t n);
// The legend's colours for "a colour per cluster", and for the glyphs in the given face colouring.
std::vector<Rgb> clusterLegendColours();
// `lodShown`: the LOD colourings were given their classes (else they keep the palette).
std::vector<Rgb> glyphLegendColours(FaceColoring coloring, bool lodShown);
// The fraction ramp from 0 to maxClusterFraction in a few steps (a swatch), and finely (a colour bar).
std::vector<Rgb> fractionLegendColours();
std::vector<Rgb> fractionBarColours();

}  // namespace conescope
