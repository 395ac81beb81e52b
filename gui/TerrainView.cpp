#include "TerrainView.h"

#include "MedialAxisTicks.h"
#include "MedialTerrainImage.h"

#include <QMouseEvent>
#include <QPainter>

#include <vtkImageData.h>

#include <algorithm>
#include <cmath>

namespace medial::gui {

namespace {

constexpr int kWallHeight = 110, kAxisHeight = 20, kBarWidth = 64;

}  // namespace

TerrainView::TerrainView(QWidget* parent) : QLabel(parent) {
  setObjectName("terrain");
  // The pixmap follows the width the layout gives (Ignored: it does not hold the panel wide).
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  setFixedHeight(kWallHeight + kAxisHeight);
  setAlignment(Qt::AlignLeft | Qt::AlignTop);
  setToolTip(
      "Unfolded wall: distance from the axis over the arc length (across, as the profile) and the angle "
      "(down); dark: near the axis (folds, polyps), orange: bridged across a gap. Click to fly there");
}

void TerrainView::setTerrain(vtkImageData* terrain) {
  const medial::TerrainGrey grey = medial::terrainGrey(terrain);
  if (grey.pixels.empty()) {
    image_ = QImage();
    length_ = 0;
    clear();
    return;
  }
  image_ = QImage(grey.height, grey.width, QImage::Format_RGB32);  // sections x angles
  for (int angle = 0; angle < grey.width; ++angle) {
    auto* row = reinterpret_cast<QRgb*>(image_.scanLine(angle));
    for (int section = 0; section < grey.height; ++section) {
      uint8_t rgb[3];
      medial::terrainPixelColour(grey, size_t(section) * grey.width + angle, rgb);
      row[section] = qRgb(rgb[0], rgb[1], rgb[2]);
    }
  }
  length_ = terrain->GetSpacing()[1] * std::max(0, grey.height - 1);
  low_ = grey.low;
  high_ = grey.high;
  marker_ = 0;
  redraw();
}

void TerrainView::setMarker(double arcLength) {
  marker_ = arcLength;
  if (!image_.isNull()) redraw();
}

int TerrainView::wallWidth() const { return std::max(width() - kBarWidth, 60); }

double TerrainView::arcLengthAt(int x) const {
  if (image_.isNull() || x < 0 || x >= wallWidth()) return -1;
  return (x + 0.5) / wallWidth() * length_;
}

int TerrainView::xAt(double arcLength) const {
  return int(std::lround(arcLength / std::max(length_, 1e-9) * wallWidth()));
}

void TerrainView::mousePressEvent(QMouseEvent* event) {
  const double arc = arcLengthAt(int(event->position().x()));
  if (event->button() == Qt::LeftButton && arc >= 0 && event->position().y() < kWallHeight) emit clicked(arc);
  QLabel::mousePressEvent(event);
}

void TerrainView::resizeEvent(QResizeEvent* event) {
  QLabel::resizeEvent(event);
  if (!image_.isNull()) redraw();
}

void TerrainView::redraw() {
  QPixmap picture(wallWidth() + kBarWidth, kWallHeight + kAxisHeight);
  picture.fill(palette().color(QPalette::Window));
  QPainter painter(&picture);
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(QRect(0, 0, wallWidth(), kWallHeight), image_);
  QFont small = font();
  small.setPointSizeF(small.pointSizeF() * 0.8);
  painter.setFont(small);
  painter.setPen(palette().color(QPalette::WindowText));
  // The arc-length axis under the wall, ticks as the profile's.
  const medial::AxisTicks ticks = medial::roundTicks(0, length_, std::max(2, wallWidth() / 70));
  for (const double mm : ticks.values) {
    const int x = xAt(mm);
    painter.drawLine(x, kWallHeight, x, kWallHeight + 4);
    const QString label = QString::fromStdString(ticks.label(mm));
    const int half = painter.fontMetrics().horizontalAdvance(label) / 2;
    painter.drawText(std::clamp(x - half, 0, wallWidth() - 2 * half),
                     kWallHeight + 5 + painter.fontMetrics().ascent(), label);
  }
  // The colour bar: far from the axis at the top.
  const int barX = wallWidth() + 8;
  for (int y = 0; y < kWallHeight; ++y) {
    uint8_t rgb[3];
    medial::terrainColour(uint8_t(std::lround(255.0 * (1 - (y + 0.5) / kWallHeight))), rgb);
    painter.fillRect(barX, y, 10, 1, QColor(rgb[0], rgb[1], rgb[2]));
  }
  const medial::AxisTicks bar = medial::roundTicks(low_, high_, 4);
  for (const double mm : bar.values) {
    const int y = int(std::lround((high_ - mm) / std::max(high_ - low_, 1e-9) * (kWallHeight - 1)));
    painter.drawLine(barX + 10, y, barX + 13, y);
    painter.drawText(
        barX + 15,
        std::clamp(y + painter.fontMetrics().ascent() / 2, painter.fontMetrics().ascent(), kWallHeight),
        QString::fromStdString(bar.label(mm)));
  }
  painter.drawText(barX, kWallHeight + 5 + painter.fontMetrics().ascent(), "mm");
  // The fly-through camera.
  painter.setPen(QPen(Qt::white, 2));
  painter.drawLine(xAt(marker_), 0, xAt(marker_), kWallHeight - 1);
  painter.end();
  setPixmap(picture);
}

}  // namespace medial::gui
