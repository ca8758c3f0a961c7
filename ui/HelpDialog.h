// F1: the keyboard shortcuts (read from the window's actions, so the list cannot go stale) and the
// mouse controls; the same dialog shows the other help pages (the glossary, About).
#pragma once

#include <QDialog>
#include <QList>

class QAction;

namespace conescope {

class HelpDialog : public QDialog {
    Q_OBJECT
public:
    HelpDialog(const QList<QAction*>& actions, QWidget* parent = nullptr);
    HelpDialog(const QString& title, const QString& html, QWidget* parent = nullptr);

    // The HTML the dialog shows, for tests.
    static QString shortcutsHtml(const QList<QAction*>& actions);
};

}  // namespace conescope
