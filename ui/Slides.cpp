#include "Slides.h"

#include <algorithm>

#include <QFont>
#include <QFontMetrics>
#include <QPainter>

namespace conescope {

QImage captionedSlide(const QImage& picture, const QString& title, const QString& text) {
    const int width = picture.width();
    const int margin = std::max(12, width / 60);
    QFont body(QStringLiteral("DejaVu Sans"));
    body.setPixelSize(std::max(14, width / 55));
    QFont heading = body;
    heading.setBold(true);
    heading.setPixelSize(body.pixelSize() * 5 / 4);
    const QRect column(margin, 0, width - 2 * margin, 100000);
    const QRect titleBox = QFontMetrics(heading).boundingRect(column, Qt::TextWordWrap, title);
    const QRect textBox = QFontMetrics(body).boundingRect(column, Qt::TextWordWrap, text);
    const int band = margin + titleBox.height() + margin / 2 + textBox.height() + margin;

    QImage slide(width, picture.height() + band, QImage::Format_RGB32);
    slide.fill(Qt::white);
    QPainter painter(&slide);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.drawImage(0, 0, picture);
    painter.setPen(QColor(20, 20, 20));
    int top = picture.height() + margin;
    painter.setFont(heading);
    painter.drawText(QRect(margin, top, column.width(), titleBox.height()), Qt::TextWordWrap, title);
    top += titleBox.height() + margin / 2;
    painter.setFont(body);
    painter.drawText(QRect(margin, top, column.width(), textBox.height()), Qt::TextWordWrap, text);
    return slide;
}

QString slideFileName(int number) { return QStringLiteral("slide-%1.png").arg(number, 2, 10, QLatin1Char('0')); }

}  // namespace conescope
