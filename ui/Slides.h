// Slides a class can project: 16:9 pages of 1920x1080 pixels, the step's title at the top, the 3D
// picture and the figures (the cross-sections) side by side below it, the words across the bottom in
// a size read from the back of a room. The layout is in slide pixels, whatever the screen's scale,
// so the same slide comes out at QT_SCALE_FACTOR 1 and 2; pictures are rendered at the size the layout
// gives them (never scaled). Written as slide-NN.png and as one slides.pdf (Qt prints it, text as
// text) by MainWindow::exportLessonSlides and exportOrbitSlides.
#pragma once

#include <vector>

#include <QImage>
#include <QRect>
#include <QString>

class QPainter;
class vtkImageData;

namespace conescope {

constexpr int kSlideWidth = 1920, kSlideHeight = 1080;
// The words' size: as large as fits, down to the smallest a back row still reads.
constexpr int kSlideTextLargest = 34, kSlideTextSmallest = 24;

struct SlideWords {
    QString title;
    QString subtitle;  // what it is about, in grey under the title: mesh, cluster, test
    QString text;
};

// Where a slide's parts go, in slide pixels.
struct SlideLayout {
    QRect title, subtitle, picture, text;
    std::vector<QRect> figures;  // right of the picture, left to right
    int titlePixels = 0, subtitlePixels = 0, textPixels = 0;  // font sizes
};

// The layout for these words and this many figures: the words as large as they fit while the
// pictures keep most of the height.
SlideLayout layoutSlide(const SlideWords& words, int figureCount);

struct Slide {
    SlideWords words;
    SlideLayout layout;
    QImage picture;               // layout.picture's size
    std::vector<QImage> figures;  // layout.figures' sizes
};

// Paints a slide on a painter whose coordinates are slide pixels (an image or a PDF page).
void paintSlide(QPainter& painter, const Slide& slide);
// kSlideWidth x kSlideHeight, RGB.
QImage slideImage(const Slide& slide);
// One page per slide, 16:9 (13.33 x 7.5 inches, as presentation programs make them), text kept as
// text. Throws std::runtime_error naming the path when it cannot be written.
void writeSlidesPdf(const std::vector<Slide>& slides, const QString& path);

// "slide-01.png", "slide-02.png", ...: the names sort in the order the slides are shown.
QString slideFileName(int number);
// The PDF beside them.
QString slidesPdfName();

// An RGB(A) image VTK rendered (rows bottom up) as a QImage (rows top down).
QImage imageOf(vtkImageData* image);

}  // namespace conescope
