#include "VtkView.h"

#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QSurfaceFormat>
#include <QWheelEvent>

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <cmath>

namespace medial::gui {

namespace {

// GL constants used in paintGL, spelt out to avoid pulling a GL loader header next to Qt's.
constexpr unsigned int kDrawFramebuffer = 0x8CA9;  // GL_DRAW_FRAMEBUFFER
constexpr unsigned int kColorBufferBit = 0x00004000;
constexpr int kNearest = 0x2600;

}  // namespace

void VtkView::setDefaultSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setSamples(0);  // VTK does its own multisampling in its framebuffers
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  QSurfaceFormat::setDefaultFormat(format);
}

VtkView::VtkView(QWidget* parent) : QOpenGLWidget(parent) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
  setMinimumSize(200, 150);

  window_->SetOwnContext(false);  // Qt owns the context
  window_->SetFrameBlitModeToNoBlit();
  window_->SetReadyForRendering(false);
  window_->SetMultiSamples(0);

  auto style = vtkNew<vtkInteractorStyleTrackballCamera>();
  interactor_->SetInteractorStyle(style);
  interactor_->SetRenderWindow(window_);
  interactor_->EnableRenderOff();  // Qt decides when to paint: the interactor asks through RenderEvent

  auto callback = vtkNew<vtkCallbackCommand>();
  callback->SetClientData(this);
  callback->SetCallback([](vtkObject* caller, unsigned long eventId, void* clientData, void* callData) {
    static_cast<VtkView*>(clientData)->onVtkEvent(caller, eventId, callData);
  });
  window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, callback);
  window_->AddObserver(vtkCommand::WindowIsCurrentEvent, callback);
  window_->AddObserver(vtkCommand::WindowSupportsOpenGLEvent, callback);
  window_->AddObserver(vtkCommand::WindowIsDirectEvent, callback);
  interactor_->AddObserver(vtkCommand::RenderEvent, callback);
}

VtkView::~VtkView() {
  makeCurrent();
  window_->Finalize();  // releases VTK's GL resources while Qt's context still exists
  doneCurrent();
}

vtkGenericOpenGLRenderWindow* VtkView::renderWindow() const { return window_; }

vtkGenericRenderWindowInteractor* VtkView::interactor() const { return interactor_; }

void VtkView::addRenderer(vtkRenderer* renderer) { window_->AddRenderer(renderer); }

void VtkView::onVtkEvent(vtkObject*, unsigned long eventId, void* callData) {
  switch (eventId) {
    case vtkCommand::WindowMakeCurrentEvent:
      // VTK asks ~20 times a frame; makeCurrent() rebinds Qt's framebuffer, so only when needed.
      if (QOpenGLContext::currentContext() != context()) makeCurrent();
      break;
    case vtkCommand::WindowIsCurrentEvent:
      *static_cast<bool*>(callData) = QOpenGLContext::currentContext() == context() && context() != nullptr;
      break;
    case vtkCommand::WindowSupportsOpenGLEvent:
    case vtkCommand::WindowIsDirectEvent:
      *static_cast<int*>(callData) = 1;
      break;
    case vtkCommand::RenderEvent:
      update();
      break;
    default:
      break;
  }
}

void VtkView::initializeGL() {
  window_->SetIsDirect(true);
  window_->SetMapped(true);
  window_->SetReadyForRendering(true);
  const qreal ratio = devicePixelRatioF();
  window_->SetSize(std::lround(width() * ratio), std::lround(height() * ratio));
  window_->OpenGLInitContext();  // loads GL entry points (GLEW) for this context
  interactor_->Initialize();
  interactor_->SetSize(window_->GetSize());
  initialized_ = true;
}

void VtkView::resizeGL(int width, int height) {
  const qreal ratio = devicePixelRatioF();
  const int w = std::lround(width * ratio), h = std::lround(height * ratio);
  window_->SetSize(w, h);
  interactor_->SetSize(w, h);
  interactor_->InvokeEvent(vtkCommand::ConfigureEvent);
}

void VtkView::paintGL() {
  if (!initialized_) return;
  window_->Render();

  // VTK rendered into its display framebuffer; copy it into the widget's, then make alpha opaque (a
  // grab would otherwise come out transparent where VTK wrote alpha < 1).
  vtkOpenGLState* state = window_->GetState();
  state->Reset();  // Qt changed GL state behind VTK's cache
  state->Push();
  const int* size = window_->GetSize();
  state->vtkglBindFramebuffer(kDrawFramebuffer, defaultFramebufferObject());
  window_->BlitDisplayFramebuffer(0, 0, 0, size[0], size[1], 0, 0, size[0], size[1], kColorBufferBit,
                                  kNearest);
  state->vtkglColorMask(false, false, false, true);
  state->vtkglClearColor(0, 0, 0, 1);
  state->vtkglClear(kColorBufferBit);
  state->Pop();
  state->vtkglBindFramebuffer(kDrawFramebuffer, defaultFramebufferObject());

  if (overlay_) {
    const QImage image = overlay_();
    if (!image.isNull()) {
      QPainter painter(this);
      painter.drawImage(rect(), image);
    }
  }
  if (stroke_.size() > 1) {  // the stroke being drawn, over the picture
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(20, 20, 20), 2.0));
    painter.drawPolyline(stroke_.constData(), static_cast<int>(stroke_.size()));
  }
}

void VtkView::setDrawingMode(bool on) {
  drawing_ = on;
  stroke_.clear();
  setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
  update();
}

void VtkView::setEventPosition(const QPointF& position, Qt::KeyboardModifiers modifiers, int repeat) {
  const qreal ratio = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(
      static_cast<int>(position.x() * ratio), static_cast<int>(position.y() * ratio),
      (modifiers & Qt::ControlModifier) ? 1 : 0, (modifiers & Qt::ShiftModifier) ? 1 : 0, 0, repeat);
  interactor_->SetAltKey((modifiers & Qt::AltModifier) ? 1 : 0);
}

void VtkView::mousePressEvent(QMouseEvent* event) {
  if (interaction_ && interaction_->mousePress(event)) return;
  if (event->button() == Qt::LeftButton) pressPosition_ = event->position();
  if (drawing_ && event->button() == Qt::LeftButton) {
    stroke_ = {event->position()};
    return;
  }
  setEventPosition(event->position(), event->modifiers());
  switch (event->button()) {
    case Qt::LeftButton:
      interactor_->InvokeEvent(vtkCommand::LeftButtonPressEvent);
      break;
    case Qt::MiddleButton:
      interactor_->InvokeEvent(vtkCommand::MiddleButtonPressEvent);
      break;
    case Qt::RightButton:
      interactor_->InvokeEvent(vtkCommand::RightButtonPressEvent);
      break;
    default:
      break;
  }
}

void VtkView::mouseDoubleClickEvent(QMouseEvent* event) {
  setEventPosition(event->position(), event->modifiers(), 1);
  if (event->button() == Qt::LeftButton) interactor_->InvokeEvent(vtkCommand::LeftButtonPressEvent);
}

void VtkView::mouseReleaseEvent(QMouseEvent* event) {
  if (interaction_ && interaction_->mouseRelease(event)) return;
  if (drawing_ && event->button() == Qt::LeftButton) {
    const QVector<QPointF> stroke = stroke_;
    stroke_.clear();
    update();
    if (stroke.size() > 2) emit strokeDrawn(stroke);
    return;
  }
  if (event->button() == Qt::LeftButton && (event->position() - pressPosition_).manhattanLength() < 4)
    emit clicked(event->position(), event->modifiers());
  setEventPosition(event->position(), event->modifiers());
  switch (event->button()) {
    case Qt::LeftButton:
      interactor_->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
      break;
    case Qt::MiddleButton:
      interactor_->InvokeEvent(vtkCommand::MiddleButtonReleaseEvent);
      break;
    case Qt::RightButton:
      interactor_->InvokeEvent(vtkCommand::RightButtonReleaseEvent);
      break;
    default:
      break;
  }
}

void VtkView::mouseMoveEvent(QMouseEvent* event) {
  if (interaction_ && interaction_->mouseMove(event)) return;
  if (drawing_ && !stroke_.isEmpty() && (event->buttons() & Qt::LeftButton)) {
    stroke_.append(event->position());
    update();
    return;
  }
  setEventPosition(event->position(), event->modifiers());
  interactor_->InvokeEvent(vtkCommand::MouseMoveEvent);
}

void VtkView::wheelEvent(QWheelEvent* event) {
  if (interaction_ && interaction_->wheel(event)) {
    event->accept();
    return;
  }
  setEventPosition(event->position(), event->modifiers());
  // One VTK wheel step per notch (120 units); touchpads send smaller deltas, which add up.
  wheelRemainder_ += event->angleDelta().y();
  for (; wheelRemainder_ >= 120; wheelRemainder_ -= 120)
    interactor_->InvokeEvent(vtkCommand::MouseWheelForwardEvent);
  for (; wheelRemainder_ <= -120; wheelRemainder_ += 120)
    interactor_->InvokeEvent(vtkCommand::MouseWheelBackwardEvent);
  event->accept();
}

void VtkView::keyPressEvent(QKeyEvent* event) {
  if (interaction_ && interaction_->keyPress(event)) return;
  if (event->key() == Qt::Key_R) {
    emit resetCameraRequested();
    return;
  }
  // Keys VTK's style would use to quit the application (e, q) stay with Qt.
  if (event->key() == Qt::Key_E || event->key() == Qt::Key_Q || event->text().isEmpty()) {
    QOpenGLWidget::keyPressEvent(event);
    return;
  }
  const QPoint position = mapFromGlobal(QCursor::pos());
  setEventPosition(position, event->modifiers(), event->isAutoRepeat() ? 1 : 0);
  const QByteArray text = event->text().toLatin1();
  interactor_->SetKeyCode(text.isEmpty() ? 0 : text[0]);
  interactor_->SetKeySym(text.constData());
  interactor_->InvokeEvent(vtkCommand::KeyPressEvent);
  interactor_->InvokeEvent(vtkCommand::CharEvent);
}

void VtkView::keyReleaseEvent(QKeyEvent* event) {
  const QByteArray text = event->text().toLatin1();
  interactor_->SetKeyCode(text.isEmpty() ? 0 : text[0]);
  interactor_->InvokeEvent(vtkCommand::KeyReleaseEvent);
}

void VtkView::enterEvent(QEnterEvent* event) {
  setEventPosition(event->position(), Qt::NoModifier);
  interactor_->InvokeEvent(vtkCommand::EnterEvent);
}

void VtkView::leaveEvent(QEvent*) { interactor_->InvokeEvent(vtkCommand::LeaveEvent); }

}  // namespace medial::gui
