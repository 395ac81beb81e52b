// VtkView: a QOpenGLWidget hosting a vtkGenericOpenGLRenderWindow with full mouse interaction, without
// VTK's Qt module (Debian builds it for Qt5 only). The recipe is in docs/ARCHITECTURE.md §9: VTK renders
// into its own framebuffers inside Qt's context, and paintGL blits the result into the widget's.
#pragma once

#include <QImage>
#include <QOpenGLWidget>
#include <QPointF>
#include <QVector>

#include <vtkNew.h>

#include <functional>

class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkRenderer;
class vtkObject;

namespace medial::gui {

// Takes the view's mouse and key events before the camera does (the skeleton editor); each returns true
// when it used the event, which then does not reach the camera.
class ViewInteraction {
 public:
  virtual ~ViewInteraction() = default;
  virtual bool mousePress(QMouseEvent*) { return false; }
  virtual bool mouseMove(QMouseEvent*) { return false; }
  virtual bool mouseRelease(QMouseEvent*) { return false; }
  virtual bool wheel(QWheelEvent*) { return false; }
  virtual bool keyPress(QKeyEvent*) { return false; }
};

class VtkView : public QOpenGLWidget {
  Q_OBJECT

 public:
  explicit VtkView(QWidget* parent = nullptr);
  ~VtkView() override;

  vtkGenericOpenGLRenderWindow* renderWindow() const;
  vtkGenericRenderWindowInteractor* interactor() const;
  void addRenderer(vtkRenderer* renderer);

  // Sets the default surface format VTK needs (OpenGL 3.2 core, depth 24, stencil 8, alpha 8). Call
  // before constructing the QApplication.
  static void setDefaultSurfaceFormat();

  // Drawing mode: a left drag draws a stroke (shown over the view) instead of rotating the camera.
  void setDrawingMode(bool on);
  bool drawingMode() const { return drawing_; }
  // Events go to `interaction` first (null: the camera only). The view does not own it.
  void setInteraction(ViewInteraction* interaction) { interaction_ = interaction; }
  // An image painted over the rendered frame, stretched to the view (e.g. the ghost view's importance
  // map), asked for after each render; null function or null image: none.
  void setOverlay(std::function<QImage()> overlay) { overlay_ = std::move(overlay); }

 signals:
  // Key R: the owner resets the camera its own way.
  void resetCameraRequested();
  // A left click without a drag, at a widget position (picking).
  void clicked(const QPointF& position, Qt::KeyboardModifiers modifiers);
  // A stroke drawn in drawing mode, in widget positions.
  void strokeDrawn(const QVector<QPointF>& positions);

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  void onVtkEvent(vtkObject* caller, unsigned long eventId, void* callData);
  // Tells the interactor where the pointer is and which modifiers are down (VTK's y axis points up).
  void setEventPosition(const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat = 0);

  vtkNew<vtkGenericOpenGLRenderWindow> window_;
  vtkNew<vtkGenericRenderWindowInteractor> interactor_;
  bool initialized_ = false;
  bool drawing_ = false;
  ViewInteraction* interaction_ = nullptr;
  std::function<QImage()> overlay_;
  QVector<QPointF> stroke_;  // the stroke being drawn
  QPointF pressPosition_;    // where the left button went down (click detection)
  int wheelRemainder_ = 0;   // angle delta not yet turned into wheel steps
};

}  // namespace medial::gui
