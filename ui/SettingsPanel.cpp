#include "SettingsPanel.h"

#include <algorithm>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include "Glossary.h"
#include "core/SettingsSchema.h"

namespace conescope {

namespace {

// A combo box listing an enum by the names the CLI accepts; the item data is the enum's index.
template <typename Enum>
QComboBox* enumBox(const std::vector<Enum>& values, QWidget* parent) {
    auto* box = new QComboBox(parent);
    for (Enum value : values) box->addItem(QString::fromStdString(toString(value)), int(value));
    return box;
}

template <typename Enum>
Enum enumOf(const QComboBox* box) {
    return Enum(box->currentData().toInt());
}

template <typename Enum>
void selectEnum(QComboBox* box, Enum value) {
    box->setCurrentIndex(std::max(0, box->findData(int(value))));
}

QSpinBox* countBox(int minimum, int maximum, QWidget* parent) {
    auto* box = new QSpinBox(parent);
    box->setRange(minimum, maximum);
    // Typing "124" must not rebuild the clusters for "1" and "12" first.
    box->setKeyboardTracking(false);
    return box;
}

QDoubleSpinBox* weightBox(double maximum, double step, QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(0.0, maximum);
    box->setSingleStep(step);
    box->setDecimals(3);
    box->setKeyboardTracking(false);
    return box;
}

// `list` with its first (the displayed) entry replaced by `value`: choosing in a box must not keep
// the previous choice as a hidden extra result. Entries given besides (the command line's
// `--test a,b`) stay, once each.
template <typename Enum>
std::vector<Enum> withFirst(std::vector<Enum> list, Enum value) {
    if (!list.empty()) list.erase(list.begin());
    list.erase(std::remove(list.begin(), list.end(), value), list.end());
    list.insert(list.begin(), value);
    return list;
}

// K cones per cluster: 1 (the test alone), 2, 4 or 8; the item data is K.
QComboBox* coneCountBox(QWidget* parent) {
    auto* box = new QComboBox(parent);
    for (int k : {1, 2, 4, 8}) box->addItem(QString::number(k), k);
    return box;
}

// "Test", the test's box, and beside it the K-cone choice measured with it.
QHBoxLayout* besideTheTest(QComboBox* test, QComboBox* cones) {
    auto* row = new QHBoxLayout;
    auto* label = new QLabel(QObject::tr("&Test"), test->parentWidget());
    label->setBuddy(test);
    row->addWidget(label);
    row->addWidget(test, 1);
    row->addWidget(new QLabel(QObject::tr("cones per cluster"), test->parentWidget()));
    row->addWidget(cones);
    return row;
}

}  // namespace

SettingsPanel::SettingsPanel(QWidget* parent) : QWidget(parent) {
    builder_ = enumBox(allBuilders(), this);
    // meshoptimizer's meshlets hold at most 255 vertices and 512 triangles.
    maxVertices_ = countBox(3, 255, this);
    maxTriangles_ = countBox(1, 512, this);
    clusterCount_ = countBox(0, 10000000, this);
    // 0 leaves the count to the builder (Settings::clusterCount), which differs per builder.
    clusterCount_->setSpecialValueText(tr("auto (the builder's default)"));
    effort_ = enumBox(allEfforts(), this);
    clusterFile_ = new QLineEdit(this);
    clusterFile_->setPlaceholderText(tr("the mesh's cluster_id array or groups"));
    clusterFile_->setClearButtonEnabled(true);
    browseClusterFile_ = new QPushButton(tr("Browse..."), this);
    normalWeight_ = weightBox(100.0, 0.25, this);
    coneWeight_ = weightBox(1.0, 0.05, this);

    cone_ = enumBox(allConeMethods(), this);
    test_ = enumBox(allCullTests(), this);
    sphere_ = enumBox(allSphereMethods(), this);
    conesPerCluster_ = coneCountBox(this);
    projection_ = new QComboBox(this);
    projection_->addItem(tr("perspective"), false);
    projection_->addItem(tr("orthographic"), true);
    fixWinding_ = new QCheckBox(tr("Fix winding (inconsistent or inside out)"), this);
    views_ = countBox(1, 100000, this);
    distance_ = weightBox(1000.0, 0.25, this);
    distance_->setMinimum(0.01);

    auto* clusterFileRow = new QHBoxLayout;
    clusterFileRow->addWidget(clusterFile_, 1);
    clusterFileRow->addWidget(browseClusterFile_);

    auto* clustersGroup = new QGroupBox(tr("Clusters"), this);
    auto* clustersForm = new QFormLayout(clustersGroup);
    clustersForm->addRow(tr("&Builder"), builder_);
    clustersForm->addRow(tr("Max vertices"), maxVertices_);
    clustersForm->addRow(tr("Max triangles"), maxTriangles_);
    clustersForm->addRow(tr("Clusters (K)"), clusterCount_);
    clustersForm->addRow(tr("&Effort"), effort_);
    clustersForm->addRow(tr("Cluster file"), clusterFileRow);
    clustersForm->addRow(tr("Normal weight"), normalWeight_);
    clustersForm->addRow(tr("Cone weight"), coneWeight_);
    clustersForm->addRow(fixWinding_);

    auto* cullingGroup = new QGroupBox(tr("Culling"), this);
    auto* cullingForm = new QFormLayout(cullingGroup);
    cullingForm->addRow(tr("&Cone"), cone_);
    cullingForm->addRow(besideTheTest(test_, conesPerCluster_));
    cullingForm->addRow(tr("Sphere"), sphere_);
    cullingForm->addRow(tr("&Projection"), projection_);

    auto* orbitGroup = new QGroupBox(tr("Orbit"), this);
    auto* orbitForm = new QFormLayout(orbitGroup);
    orbitForm->addRow(tr("Views"), views_);
    orbitForm->addRow(tr("Distance"), distance_);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(clustersGroup);
    layout->addWidget(cullingGroup);
    layout->addWidget(orbitGroup);
    layout->addStretch(1);

    describeWidgets();
    setSettings(Settings{});

    for (QComboBox* box : {builder_, effort_, cone_, test_, sphere_, projection_, conesPerCluster_})
        connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, &SettingsPanel::emitChanged);
    for (QSpinBox* box : {maxVertices_, maxTriangles_, clusterCount_, views_})
        connect(box, qOverload<int>(&QSpinBox::valueChanged), this, &SettingsPanel::emitChanged);
    for (QDoubleSpinBox* box : {normalWeight_, coneWeight_, distance_})
        connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this, &SettingsPanel::emitChanged);
    connect(clusterFile_, &QLineEdit::editingFinished, this, [this]() {
        if (clusterFile_->text().toStdString() != base_.clusterFile) emitChanged();
    });
    connect(fixWinding_, &QCheckBox::toggled, this, &SettingsPanel::emitChanged);
    connect(browseClusterFile_, &QPushButton::clicked, this, &SettingsPanel::browseClusterFile);
}

Settings SettingsPanel::settings() const {
    Settings settings = base_;
    settings.builder = enumOf<Builder>(builder_);
    settings.limits.maxVertices = size_t(maxVertices_->value());
    settings.limits.maxTriangles = size_t(maxTriangles_->value());
    settings.clusterCount = size_t(clusterCount_->value());
    settings.effort = enumOf<Effort>(effort_);
    settings.clusterFile = clusterFile_->text().toStdString();
    settings.normalWeight = normalWeight_->value();
    settings.meshoptConeWeight = float(coneWeight_->value());
    settings.cones = withFirst(base_.cones, enumOf<ConeMethod>(cone_));
    settings.tests = withFirst(base_.tests, enumOf<CullTest>(test_));
    settings.sphere = enumOf<SphereMethod>(sphere_);
    settings.conesPerCluster = uint32_t(conesPerCluster_->currentData().toInt());
    settings.orthographic = projection_->currentData().toBool();
    settings.fixWinding = fixWinding_->isChecked();
    settings.views = size_t(views_->value());
    settings.distance = distance_->value();
    return settings;
}

void SettingsPanel::setSettings(const Settings& settings) {
    // Shown already (the panel's own change coming back from the session): the widgets stay as typed.
    if (sameSettings(settings, this->settings())) {
        base_ = settings;
        return;
    }
    base_ = settings;
    const QSignalBlocker blockers[] = {
        QSignalBlocker(builder_),      QSignalBlocker(maxVertices_), QSignalBlocker(maxTriangles_),
        QSignalBlocker(clusterCount_), QSignalBlocker(effort_),      QSignalBlocker(clusterFile_), QSignalBlocker(normalWeight_),
        QSignalBlocker(coneWeight_),   QSignalBlocker(cone_),        QSignalBlocker(test_),
        QSignalBlocker(sphere_),       QSignalBlocker(projection_),  QSignalBlocker(fixWinding_),
        QSignalBlocker(views_),        QSignalBlocker(distance_),    QSignalBlocker(conesPerCluster_)};
    selectEnum(builder_, settings.builder);
    maxVertices_->setValue(int(settings.limits.maxVertices));
    maxTriangles_->setValue(int(settings.limits.maxTriangles));
    clusterCount_->setValue(int(settings.clusterCount));
    selectEnum(effort_, settings.effort);
    clusterFile_->setText(QString::fromStdString(settings.clusterFile));
    normalWeight_->setValue(settings.normalWeight);
    coneWeight_->setValue(double(settings.meshoptConeWeight));
    if (!settings.cones.empty()) selectEnum(cone_, settings.cones.front());
    if (!settings.tests.empty()) selectEnum(test_, settings.tests.front());
    selectEnum(sphere_, settings.sphere);
    conesPerCluster_->setCurrentIndex(std::max(0, conesPerCluster_->findData(int(settings.conesPerCluster))));
    projection_->setCurrentIndex(settings.orthographic ? 1 : 0);
    fixWinding_->setChecked(settings.fixWinding);
    views_->setValue(int(settings.views));
    distance_->setValue(settings.distance);
    enableForBuilder();
    for (QComboBox* box : {builder_, effort_, cone_, test_, sphere_, projection_, conesPerCluster_}) describeChoice(box);
}

void SettingsPanel::emitChanged() {
    enableForBuilder();
    base_ = settings();
    emit settingsChanged(base_);
}

void SettingsPanel::enableForBuilder() {
    // Which builder uses which field is the schema's to say; the panel only maps fields to widgets.
    const Settings current = settings();
    const std::pair<const char*, std::vector<QWidget*>> widgetsOfField[] = {
        {"max_vertices", {maxVertices_}},   {"max_triangles", {maxTriangles_}},
        {"clusters_target", {clusterCount_}}, {"effort", {effort_}}, {"cluster_file", {clusterFile_, browseClusterFile_}},
        {"normal_weight", {normalWeight_}}, {"cone_weight", {coneWeight_}}};
    for (const auto& [key, widgets] : widgetsOfField)
        for (QWidget* widget : widgets) widget->setEnabled(fieldMatters(settingField(key), current));
}

void SettingsPanel::describeWidgets() {
    // The command line's help for the setting (the schema's), then the words a newcomer needs.
    const std::pair<const char*, std::vector<std::pair<QWidget*, QString>>> described[] = {
        {"builder", {{builder_, explain(QStringLiteral("builder"))}}},
        {"max_vertices", {{maxVertices_, tr("A cluster may use at most this many distinct vertices (a GPU meshlet's limit).")}}},
        {"max_triangles", {{maxTriangles_, tr("A cluster may hold at most this many triangles.")}}},
        {"clusters_target", {{clusterCount_, tr("How many clusters to make. Auto: the optimized builder aims at the count "
                                               "meshoptimizer reaches at these limits, so comparisons are at equal counts; "
                                               "k-means uses triangles / max triangles; the meshlet and meshopt builders "
                                               "always choose their own count.")}}},
        {"effort", {{effort_, tr("How long the optimized builder searches: fast refines meshoptimizer's meshlets, balanced "
                                 "(default) adds a few annealing sweeps, best grows its own clusters and searches longest "
                                 "(docs/benchmarks.md has the measured trade).")}}},
        {"cluster_file", {{clusterFile_, tr("The file builder's clusters: a text file with one cluster id per face; empty "
                                            "takes the mesh's own cluster_id array.")},
                          {browseClusterFile_, tr("Choose the text file of cluster ids.")}}},
        {"normal_weight", {{normalWeight_, tr("meshlet and k-means builders: how much they prefer faces that look the same "
                                              "way (narrow cones) over faces close together (0: closeness only).")}}},
        {"cone_weight", {{coneWeight_, tr("meshopt builder: meshopt_buildMeshlets' cone_weight, its own preference for "
                                          "narrow cones.")}}},
        {"cones", {{cone_, explain(QStringLiteral("normal cone")) + tr(" How the cone is found:")}}},
        {"tests", {{test_, tr("The cheap test that decides from the cull eye whether a whole cluster faces away.")}}},
        {"cones_per_cluster", {{conesPerCluster_, tr("Besides the test, each cluster's faces split into K sub-groups with a "
                                                     "cone and an apex each: the K-cone record's culling, from the eye and over "
                                                     "the views (1: one cone only). The optimized builder makes its clusters for "
                                                     "K cones.")}}},
        {"sphere", {{sphere_, explain(QStringLiteral("bounding sphere")) + tr(" Ritter's is quick, minimal the smallest.")}}},
        {"orthographic", {{projection_, tr("Perspective: the eye is a point. Orthographic: the eye is infinitely far away and "
                                           "every view vector is the same direction.")}}},
        {"fix_winding", {{fixWinding_, tr("Turns faces wound against their neighbours, and inside-out pieces, outward, so that "
                                          "every normal points out of the surface.")}}},
        {"views", {{views_, explain(QStringLiteral("orbit")) + tr(" How many eye positions it has.")}}},
        {"distance", {{distance_, tr("How far the orbit's eyes are from the mesh centre, in half the diagonal of its bounding "
                                     "box (3: about three mesh sizes away).")}}},
    };
    for (const auto& [key, widgets] : described) {
        const QString help = QString::fromStdString(settingHelp(settingField(key)));
        for (const auto& [widget, words] : widgets) {
            // A box that takes one choice says what the chosen one means (describeChoice), not the
            // command line's help for a list of them.
            if (auto* box = qobject_cast<QComboBox*>(widget)) {
                box->setProperty("about", words);
                continue;
            }
            widget->setToolTip(QStringLiteral("<p>%1</p><p><i>%2</i></p>").arg(words.toHtmlEscaped(), help.toHtmlEscaped()));
            widget->setWhatsThis(words + QStringLiteral("\n\n") + help);
        }
    }
    // Each choice says what it is.
    for (int i = 0; i < builder_->count(); ++i) builder_->setItemData(i, explain(Builder(builder_->itemData(i).toInt())), Qt::ToolTipRole);
    for (int i = 0; i < effort_->count(); ++i) effort_->setItemData(i, explain(Effort(effort_->itemData(i).toInt())), Qt::ToolTipRole);
    for (int i = 0; i < cone_->count(); ++i) cone_->setItemData(i, explain(ConeMethod(cone_->itemData(i).toInt())), Qt::ToolTipRole);
    for (int i = 0; i < test_->count(); ++i) test_->setItemData(i, explain(CullTest(test_->itemData(i).toInt())), Qt::ToolTipRole);
    for (int i = 0; i < sphere_->count(); ++i)
        sphere_->setItemData(i, explain(SphereMethod(sphere_->itemData(i).toInt())), Qt::ToolTipRole);
    for (int i = 0; i < conesPerCluster_->count(); ++i)
        conesPerCluster_->setItemData(i, i == 0 ? tr("One cone per cluster: the test alone.")
                                                : tr("%1 sub-groups per cluster, a cone each.").arg(conesPerCluster_->itemData(i).toInt()),
                                      Qt::ToolTipRole);
    projection_->setItemData(0, tr("The eye is a point: each face is seen from its own direction."), Qt::ToolTipRole);
    projection_->setItemData(1, tr("The eye is infinitely far away: every face is seen from the same direction."), Qt::ToolTipRole);
    for (QComboBox* box : {builder_, effort_, cone_, test_, sphere_, projection_, conesPerCluster_}) {
        connect(box, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, box]() { describeChoice(box); });
        describeChoice(box);
    }
}

void SettingsPanel::describeChoice(QComboBox* box) {
    const QString about = box->property("about").toString();
    const QString chosen = box->currentText(), meaning = box->currentData(Qt::ToolTipRole).toString();
    box->setToolTip(QStringLiteral("<p>%1</p><p><b>%2</b>: %3</p>").arg(about.toHtmlEscaped(), chosen.toHtmlEscaped(), meaning.toHtmlEscaped()));
    box->setWhatsThis(about + QStringLiteral("\n\n") + tr("Chosen: %1. %2").arg(chosen, meaning));
}

void SettingsPanel::browseClusterFile() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Cluster file"), clusterFile_->text(),
        tr("Cluster files (*.json *.meshlets *.txt *.ids);;meshoptimizer meshlets (*.json *.meshlets);;Cluster ids (*.txt *.ids);;All files (*)"));
    if (path.isEmpty()) return;
    clusterFile_->setText(path);
    emitChanged();
}

}  // namespace conescope
