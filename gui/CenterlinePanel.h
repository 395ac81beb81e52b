// CenterlinePanel: TSK centerline (vtkMedialTskCenterline) from a volume: a label or a threshold, a seed
// clicked in a slice view; then the sections' min/max diameter along the arc length (Qt Charts), the
// unfolded wall, and a fly-through (play/pause, speed, position slider) that moves the 3-D camera inside
// the tube.
#pragma once

#include "FilterPanel.h"
#include "FlyThrough.h"

#include <QImage>
#include <QTimer>

#include <array>
#include <optional>

class QChartView;
class QLabel;
class QPushButton;
class QSlider;
class QDoubleSpinBox;
class QLineSeries;
class QScatterSeries;
class vtkImageData;
class vtkTable;

namespace medial::gui {

class CenterlinePanel : public FilterPanel {
  Q_OBJECT

 public:
  CenterlinePanel(ObjectList* objects, QWidget* parent = nullptr);

  // P0 in physical coordinates (mm), e.g. from a click in a slice view.
  void setSeed(const std::array<double, 3>& seed);
  void clearSeed();
  std::optional<std::array<double, 3>> seed() const { return seed_; }

  const FlyThrough& flyThrough() const { return fly_; }
  // Fly-through position in mm along the centerline.
  void setPosition(double arcLength);
  double position() const { return position_; }
  void play(bool on);
  bool isPlaying() const { return timer_.isActive(); }
  int profilePoints() const;
  // Sections on bridges across gaps (collapsed segments), marked along the profile's axis.
  int bridgedProfilePoints() const;
  const QImage& terrainImage() const { return terrainImage_; }

 signals:
  // The camera should stand at `eye` looking at `focal` (the slice views follow `eye`).
  void flyTo(const std::array<double, 3>& eye, const std::array<double, 3>& focal,
             const std::array<double, 3>& up);

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  Steps steps(vtkAlgorithm* filter) override;

 private:
  void buildProfile(vtkTable* profile);
  void showBridges(SceneObject* object, vtkPolyData* line);
  void showTerrain(vtkImageData* terrain);
  void step();

  std::optional<std::array<double, 3>> seed_;
  QLabel* seedLabel_ = nullptr;
  QChartView* chart_ = nullptr;
  QLineSeries* minDiameter_ = nullptr;
  QLineSeries* maxDiameter_ = nullptr;
  QLabel* terrain_ = nullptr;
  QImage terrainImage_;
  QLineSeries* marker_ = nullptr;
  QScatterSeries* bridged_ = nullptr;
  QSlider* positionSlider_ = nullptr;
  QPushButton* playButton_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;
  QTimer timer_;
  FlyThrough fly_;
  double position_ = 0;
};

}  // namespace medial::gui
