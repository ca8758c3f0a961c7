// What the window test programs share: the window opened as a user sees it, pictures of it for
// looking at when a test fails, and small readers of its views.
#pragma once

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QLabel>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "MainWindow.h"
#include "StatisticsPanel.h"

namespace conescope::testing {

struct WindowFixture {
    std::unique_ptr<MainWindow> window_;
    QString outputDir_;
    QTemporaryDir temporary_;

    // The window at a fixed size, shown, active (no window manager under Xvfb: its shortcuts apply
    // only so), with error dialogs off and the tests' own settings.
    void openWindow() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ConeScopeTests"));
        QCoreApplication::setApplicationName(QStringLiteral("conescope-ui-tests"));
        outputDir_ = qEnvironmentVariable("CONESCOPE_UI_TEST_OUTPUT", QDir::tempPath());
        QVERIFY(temporary_.isValid());
        window_ = std::make_unique<MainWindow>();
        window_->setErrorDialogsEnabled(false);
        window_->resize(1280, 960);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        QApplication::setActiveWindow(window_.get());
        QCOMPARE(QApplication::activeWindow(), window_.get());
    }

    // The whole window as the user sees it, for looking at when a test fails.
    void saveWindowPicture(const QString& name) {
        QApplication::processEvents();
        window_->grab().save(QDir(outputDir_).filePath(name));
    }
};

// Selects the entry of a combo box whose text is `name`, as a user would.
inline void chooseInCombo(QComboBox* box, const std::string& name) {
    const int index = box->findText(QString::fromStdString(name));
    QVERIFY2(index >= 0, name.c_str());
    box->setCurrentIndex(index);
}

inline vtkRenderer* observerRenderer(MainWindow& window) {
    return window.observerView()->renderWindow()->GetRenderers()->GetFirstRenderer();
}

// What is wrong with the statistics panel's rows as shown, empty when nothing: a wrapped value lower
// than its text needs, a value over the next row's, or a gap between two rows (hidden rows between).
inline QString statisticsLayoutFault(const StatisticsPanel& panel) {
    QApplication::processEvents();
    std::vector<std::pair<QRect, QString>> shown;
    for (const QString& row : panel.rows()) {
        auto* value = panel.findChild<QLabel*>(row);
        if (!value || !value->isVisibleTo(&panel)) continue;
        if (value->wordWrap() && value->height() < value->heightForWidth(value->width()))
            return QStringLiteral("%1: %2 high, needs %3").arg(row).arg(value->height()).arg(value->heightForWidth(value->width()));
        shown.emplace_back(value->geometry(), row);
    }
    std::sort(shown.begin(), shown.end(), [](const auto& a, const auto& b) { return a.first.top() < b.first.top(); });
    for (size_t i = 0; i + 1 < shown.size(); ++i) {
        const int gap = shown[i + 1].first.top() - (shown[i].first.bottom() + 1);
        if (gap < 0) return QStringLiteral("%1 runs %2 px over %3").arg(shown[i].second).arg(-gap).arg(shown[i + 1].second);
        if (gap > 12) return QStringLiteral("%1 px between %2 and %3").arg(gap).arg(shown[i].second, shown[i + 1].second);
    }
    return {};
}

// Every legend entry's text, one per line.
inline QString legendText(const ClusterScene& scene) {
    QString text;
    for (const LegendEntry& entry : scene.legend().entries()) text += QString::fromStdString(entry.label) + '\n';
    return text;
}

}  // namespace conescope::testing
