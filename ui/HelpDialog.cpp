#include "HelpDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace conescope {

QString HelpDialog::shortcutsHtml(const QList<QAction*>& actions) {
    QString html = QStringLiteral(
        "<h2>ConeScope</h2><p>Clusters whose every face turns away from the <b>cull eye</b> are culled by the chosen "
        "test; the <b>observer</b> camera looks at the result from anywhere.</p>"
        "<h3>Keyboard</h3><table border='1' cellspacing='0' cellpadding='4'><tr><th>Keys</th><th>Action</th></tr>");
    for (const QAction* action : actions) {
        if (action->shortcuts().isEmpty()) continue;
        QStringList keys;
        for (const QKeySequence& key : action->shortcuts()) keys << key.toString(QKeySequence::NativeText).toHtmlEscaped();
        QString text = action->text();
        text.remove(QLatin1Char('&'));
        html += QStringLiteral("<tr><td>%1</td><td>%2</td></tr>").arg(keys.join(QStringLiteral(", ")), text.toHtmlEscaped());
    }
    html += QStringLiteral(
        "</table><h3>Mouse (observer view)</h3><table border='1' cellspacing='0' cellpadding='4'>"
        "<tr><td>Left drag</td><td>rotate the observer camera</td></tr>"
        "<tr><td>Shift + left drag, middle drag</td><td>pan</td></tr>"
        "<tr><td>Wheel, right drag</td><td>zoom</td></tr>"
        "<tr><td>Left click (no drag)</td><td>pick a cluster: its cone, bounds and the test's numbers</td></tr>"
        "<tr><td>Drag the eye handle</td><td>move the cull eye</td></tr></table>"
        "<h3>Colours</h3><p>Cull decision colouring: grey = culled, blue = drawn (a face may be seen), orange = missed "
        "cull (every face faces away, the test was not sure), red = false cull (must never appear).</p>"
        "<p>Loss colouring: grey = culled, orange = lost to the test, violet = lost to the partition, blue = visible. "
        "A/B colouring: orange = culled by A only, light blue = by B only, grey = by both, slate = by neither.</p>"
        "<p>Magenta is the cull eye, turquoise the view vector v, yellow the picked cluster; the legend in the view "
        "lists what is shown.</p>");
    return html;
}

HelpDialog::HelpDialog(const QList<QAction*>& actions, QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("ConeScope help"));
    auto* browser = new QTextBrowser(this);
    browser->setHtml(shortcutsHtml(actions));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(browser);
    layout->addWidget(buttons);
    resize(560, 640);
}

}  // namespace conescope
