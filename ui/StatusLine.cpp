#include "StatusLine.h"

#include <cmath>

#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

#include "Session.h"

namespace conescope {

namespace {

QString milliseconds(double seconds) { return QString::number(1000.0 * seconds, 'f', 1) + QStringLiteral(" ms"); }

}  // namespace

StatusLine::StatusLine(QStatusBar* bar, Session* session) : QObject(bar) {
    summary_ = new QLabel(tr("No mesh"), bar);
    progress_ = new QProgressBar(bar);
    progress_->setRange(0, 100);
    progress_->setTextVisible(true);
    progress_->hide();
    cancel_ = new QPushButton(tr("Cancel"), bar);
    cancel_->hide();
    connect(cancel_, &QPushButton::clicked, session, &Session::cancel);
    // A normal widget: messages replace it for a few seconds.
    bar->addWidget(summary_, 1);
    bar->addPermanentWidget(progress_);
    bar->addPermanentWidget(cancel_);

    connect(session, &Session::taskStarted, this, [this](const QString& title) {
        progress_->setValue(0);
        showStage(title);
        progress_->show();
        cancel_->show();
    });
    connect(session, &Session::progressChanged, this, [this](double fraction, const QString& stage) {
        progress_->setValue(int(std::lround(100.0 * fraction)));
        showStage(stage);
    });
    connect(session, &Session::idle, this, [this]() {
        progress_->hide();
        cancel_->hide();
        progress_->setMinimumWidth(0);
    });
}

void StatusLine::showStage(const QString& stage) {
    progress_->setFormat(stage + QStringLiteral(" %p%"));
    // Wide enough for the whole text at 100 %; it only grows while a task runs, so the bar does not
    // jump about from stage to stage.
    const int needed = progress_->fontMetrics().horizontalAdvance(stage + QStringLiteral(" 100%")) + 24;
    if (needed > progress_->minimumWidth()) progress_->setMinimumWidth(needed);
}

bool StatusLine::progressShown() const { return progress_->isVisible(); }

void StatusLine::showSummary(const Session& session) {
    const PreparedMesh* prepared = session.preparedMesh();
    const ClusterSet* clusters = session.clusters();
    if (!prepared || !clusters) {
        summary_->setText(tr("No mesh"));
        return;
    }
    QString text = tr("%1: %2 triangles, %3 clusters (%4, %5, %6) | load %7, partition %8, bounds %9, eye %10")
                       .arg(QString::fromStdString(prepared->name))
                       .arg(QLocale().toString(qulonglong(prepared->triangles)))
                       .arg(clusters->partition.clusterCount)
                       .arg(QString::fromStdString(toString(session.settings().builder)),
                            QString::fromStdString(toString(displayedCone(session.settings()))),
                            QString::fromStdString(toString(displayedTest(session.settings()))))
                       .arg(milliseconds(prepared->prepareSeconds), milliseconds(clusters->partitionSeconds),
                            milliseconds(clusters->boundsSeconds), milliseconds(session.eyeSeconds()));
    if (!session.orbitRows().empty()) text += tr(" | orbit of %1 views measured").arg(session.orbitRows().size());
    summary_->setText(text);
}

}  // namespace conescope
