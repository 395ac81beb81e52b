// TerrainView: the unfolded wall (paper §4, Fig. 15) under the profile: the arc length across (as the
// profile's axis, with round ticks), the angle around the axis down, the wall's distance from the axis on
// the viridis map with a colour bar in mm, bridged gaps orange, the fly-through camera as a white line, and
// a click that moves the fly-through there.
#pragma once

#include <QImage>
#include <QLabel>

class vtkImageData;

namespace medial::gui {

class TerrainView : public QLabel {
  Q_OBJECT

 public:
  explicit TerrainView(QWidget* parent = nullptr);

  // The filter's unfolded wall (port 2); nullptr or an empty wall clears the view.
  void setTerrain(vtkImageData* terrain);
  void setMarker(double arcLength);
  // The wall at one pixel per section and ray: sections across, angles down.
  const QImage& image() const { return image_; }
  // The arc length (mm) at x in the widget, and back; -1 outside the wall.
  double arcLengthAt(int x) const;
  int xAt(double arcLength) const;

 signals:
  void clicked(double arcLength);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  void redraw();
  int wallWidth() const;

  QImage image_;
  double length_ = 0;          // mm from the first section to the last
  double low_ = 0, high_ = 1;  // the colour bar's range (mm)
  double marker_ = 0;
};

}  // namespace medial::gui
