// The status bar's own parts: a line summing up the mesh, its clusters and the time of each stage,
// and while a slow stage runs, its progress and a Cancel button. Messages (errors, files written)
// replace the line for a few seconds.
#pragma once

#include <QObject>

class QLabel;
class QProgressBar;
class QPushButton;
class QStatusBar;

namespace conescope {

class Session;

class StatusLine : public QObject {
    Q_OBJECT
public:
    // Adds its widgets to `bar` and follows the session's background stages; Cancel cancels them all.
    StatusLine(QStatusBar* bar, Session* session);

    void showSummary(const Session& session);
    bool progressShown() const;

private:
    void showStage(const QString& stage);

    QLabel* summary_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QPushButton* cancel_ = nullptr;
};

}  // namespace conescope
