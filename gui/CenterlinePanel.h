// CenterlinePanel: TSK centerline (vtkMedialTskCenterline) from a volume: a label or a threshold, a seed
// clicked in a slice view; then the virtual-colonoscopy tools: the sections' diameter profile
// (ProfileChart), the unfolded wall (TerrainView), and a fly-through (play/pause, forward or backward,
// speed, view angle, position slider) that moves the 3-D camera inside the tube; a click on the profile or
// the wall flies there. A run leaves the camera where the user left it.
#pragma once

#include "FilterPanel.h"
#include "FlyThrough.h"

#include <QImage>
#include <QTimer>

#include <array>
#include <optional>

class QCheckBox;
class QLabel;
class QPushButton;
class QSlider;
class QDoubleSpinBox;
class vtkCamera;
class vtkImageData;

namespace medial::gui {

class ProfileChart;
class TerrainView;

class CenterlinePanel : public FilterPanel {
  Q_OBJECT

 public:
  CenterlinePanel(ObjectList* objects, QWidget* parent = nullptr);

  // P0 in physical coordinates (mm), e.g. from a click in a slice view.
  void setSeed(const std::array<double, 3>& seed);
  void clearSeed();
  std::optional<std::array<double, 3>> seed() const { return seed_; }

  const FlyThrough& flyThrough() const { return fly_; }
  // Fly-through position in mm along the centerline (moves the camera there).
  void setPosition(double arcLength);
  double position() const { return position_; }
  void play(bool on);
  bool isPlaying() const { return timer_.isActive(); }
  // Flying and looking towards the start of the line; the camera's view angle (degrees).
  void setBackward(bool backward);
  bool backward() const;
  void setViewAngle(double degrees);
  double viewAngle() const;
  // Puts `camera` at the fly-through's position, direction and view angle.
  void applyCamera(vtkCamera* camera) const;
  int profilePoints() const;
  // Sections on bridges across gaps (collapsed segments), marked along the profile's axis.
  int bridgedProfilePoints() const;
  const QImage& terrainImage() const;
  ProfileChart* profile() const { return profile_; }
  TerrainView* terrain() const { return terrain_; }

 signals:
  // The camera should stand at `eye` looking at `focal` (the slice views follow `eye`).
  void flyTo(const std::array<double, 3>& eye, const std::array<double, 3>& focal,
             const std::array<double, 3>& up);

 protected:
  vtkSmartPointer<vtkAlgorithm> makeFilter(SceneObject* input, QString& error) override;
  void collect(vtkAlgorithm* filter, SceneObject* input, double seconds) override;
  Steps steps(vtkAlgorithm* filter) override;

 private:
  void buildFlyControls();
  void showBridges(SceneObject* object, vtkPolyData* line);
  void showLumen(SceneObject* input, vtkPolyData* surface);
  // The slider and the markers at position_, without moving the camera.
  void showPosition();
  void step();

  std::optional<std::array<double, 3>> seed_;
  QLabel* seedLabel_ = nullptr;
  ProfileChart* profile_ = nullptr;
  TerrainView* terrain_ = nullptr;
  QSlider* positionSlider_ = nullptr;
  QPushButton* playButton_ = nullptr;
  QCheckBox* backward_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;
  QDoubleSpinBox* viewAngle_ = nullptr;
  QTimer timer_;
  FlyThrough fly_;
  double position_ = 0;
};

}  // namespace medial::gui
