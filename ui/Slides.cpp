#include "Slides.h"

#include <algorithm>
#include <stdexcept>

#include <QFont>
#include <QFontMetrics>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

#include <vtkImageData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkPointData.h>

namespace conescope {

namespace {

constexpr int margin = 48, gap = 22;
constexpr int titlePixels = 52, subtitlePixels = 26;
// The pictures keep at least this much of the height while the words shrink to fit.
constexpr int picturesAtLeast = 560;

QFont slideFont(int pixels, bool bold = false) {
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(pixels);
    font.setBold(bold);
    return font;
}

// The height `text` wraps to in `width` slide pixels, measured on an image (no screen scale).
int wrappedHeight(const QString& text, const QFont& font, int width) {
    static const QImage reference(8, 8, QImage::Format_RGB32);
    if (text.isEmpty()) return 0;
    return QFontMetrics(font, &reference).boundingRect(QRect(0, 0, width, 100000), Qt::TextWordWrap, text).height();
}

}  // namespace

SlideLayout layoutSlide(const SlideWords& words, int figureCount) {
    SlideLayout layout;
    const int width = kSlideWidth - 2 * margin;
    layout.titlePixels = titlePixels;
    layout.subtitlePixels = subtitlePixels;
    int top = margin * 2 / 3;
    layout.title = QRect(margin, top, width, wrappedHeight(words.title, slideFont(titlePixels, true), width));
    top = layout.title.bottom() + 1 + 4;
    layout.subtitle = QRect(margin, top, width, wrappedHeight(words.subtitle, slideFont(subtitlePixels), width));
    top = layout.subtitle.bottom() + 1 + gap;
    // The words as large as they fit with the pictures keeping most of the height.
    int textHeight = 0;
    for (layout.textPixels = kSlideTextLargest; layout.textPixels >= kSlideTextSmallest; layout.textPixels -= 2) {
        textHeight = wrappedHeight(words.text, slideFont(layout.textPixels), width);
        if (kSlideHeight - margin * 2 / 3 - textHeight - gap - top >= picturesAtLeast) break;
    }
    layout.textPixels = std::max(layout.textPixels, kSlideTextSmallest);
    layout.text = QRect(margin, kSlideHeight - margin * 2 / 3 - textHeight, width, textHeight);
    const int height = std::max(120, layout.text.top() - gap - top);
    // Each figure a square beside the picture: one takes up to 42% of the width, two a quarter each.
    // Widths a multiple of 4: a GL read of RGB rows pads each to 4 bytes where the context says so.
    const auto fourfold = [](int pixels) { return pixels / 4 * 4; };
    const int side = figureCount == 0
                         ? 0
                         : fourfold(std::min(height, int((width - gap * figureCount) * (figureCount == 1 ? 0.42 : 0.5 / figureCount))));
    const int pictureWidth = fourfold(width - figureCount * (side + gap));
    layout.picture = QRect(margin, top, pictureWidth, height);
    for (int i = 0; i < figureCount; ++i)
        layout.figures.emplace_back(margin + pictureWidth + gap + i * (side + gap), top + (height - side) / 2, side, side);
    return layout;
}

void paintSlide(QPainter& painter, const Slide& slide) {
    const SlideLayout& layout = slide.layout;
    painter.fillRect(QRect(0, 0, kSlideWidth, kSlideHeight), Qt::white);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    painter.setPen(QColor(20, 20, 20));
    painter.setFont(slideFont(layout.titlePixels, true));
    painter.drawText(layout.title, Qt::TextWordWrap, slide.words.title);
    painter.setPen(QColor(100, 100, 100));
    painter.setFont(slideFont(layout.subtitlePixels));
    painter.drawText(layout.subtitle, Qt::TextWordWrap, slide.words.subtitle);
    if (!slide.picture.isNull()) painter.drawImage(layout.picture, slide.picture);
    for (size_t i = 0; i < slide.figures.size() && i < layout.figures.size(); ++i) {
        painter.drawImage(layout.figures[i], slide.figures[i]);
        painter.setPen(QPen(QColor(200, 200, 200), 2));
        painter.drawRect(layout.figures[i]);
    }
    painter.setPen(QColor(20, 20, 20));
    painter.setFont(slideFont(layout.textPixels));
    painter.drawText(layout.text, Qt::TextWordWrap, slide.words.text);
}

QImage slideImage(const Slide& slide) {
    QImage image(kSlideWidth, kSlideHeight, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    paintSlide(painter, slide);
    return image;
}

void writeSlidesPdf(const std::vector<Slide>& slides, const QString& path) {
    QPdfWriter writer(path);
    writer.setTitle(slides.empty() ? QString() : slides.front().words.subtitle);
    writer.setCreator(QStringLiteral("ConeScope"));
    // 960 x 540 points at 144 dots per inch: a page of exactly 1920 x 1080 slide pixels.
    writer.setPageSize(QPageSize(QSize(kSlideWidth / 2, kSlideHeight / 2), QStringLiteral("Slide 16:9"), QPageSize::ExactMatch));
    writer.setPageMargins(QMarginsF(0, 0, 0, 0));
    writer.setResolution(144);
    QPainter painter;
    if (!painter.begin(&writer)) throw std::runtime_error(path.toStdString() + ": cannot write the PDF");
    for (size_t i = 0; i < slides.size(); ++i) {
        if (i > 0 && !writer.newPage()) throw std::runtime_error(path.toStdString() + ": cannot add a page to the PDF");
        paintSlide(painter, slides[i]);
    }
    if (!painter.end()) throw std::runtime_error(path.toStdString() + ": cannot write the PDF");
}

QString slideFileName(int number) { return QStringLiteral("slide-%1.png").arg(number, 2, 10, QLatin1Char('0')); }

QString slidesPdfName() { return QStringLiteral("slides.pdf"); }

QImage imageOf(vtkImageData* image) {
    int dimensions[3];
    image->GetDimensions(dimensions);
    const int width = dimensions[0], height = dimensions[1];
    vtkUnsignedCharArray* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
    QImage result(width, height, QImage::Format_RGB32);
    if (!pixels) return result;
    const int components = pixels->GetNumberOfComponents();
    const unsigned char* data = pixels->GetPointer(0);
    for (int y = 0; y < height; ++y) {
        auto* row = reinterpret_cast<QRgb*>(result.scanLine(height - 1 - y));
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = data + size_t(components) * (size_t(y) * size_t(width) + size_t(x));
            row[x] = qRgb(p[0], p[1], p[2]);
        }
    }
    return result;
}

}  // namespace conescope
