// Slides for a lecture: a picture of the 3D view with its words in a band below it, large enough to
// read from the back of a room (MainWindow::exportLessonSlides, the replay's "slides" step).
#pragma once

#include <QImage>
#include <QString>

namespace conescope {

// `picture` above a white band holding `title` (bold) and `text`, wrapped to the picture's width.
QImage captionedSlide(const QImage& picture, const QString& title, const QString& text);

// "slide-01.png", "slide-02.png", ...: the names sort in the order the slides are shown.
QString slideFileName(int number);

}  // namespace conescope
