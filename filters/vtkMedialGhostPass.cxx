#include "vtkMedialGhostPass.h"

#include "MedialGhostShaders.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCameraPass.h>
#include <vtkDualDepthPeelingPass.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleKey.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkOrderIndependentTranslucentPass.h>
#include <vtkProperty.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkPointData.h>
#include <vtkPixelBufferObject.h>
#include <vtkImageData.h>
#include <vtkFloatArray.h>
#include <vtkTranslucentPass.h>
#include <vtk_glew.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

vtkStandardNewMacro(vtkMedialGhostPass);
vtkInformationKeyMacro(vtkMedialGhostPass, IMPORTANCE, Double);

struct vtkMedialGhostPass::Resources {
  vtkSmartPointer<vtkTextureObject> Raw;       // importance map as drawn
  vtkSmartPointer<vtkTextureObject> RawDepth;  // its depth buffer
  vtkSmartPointer<vtkTextureObject> Half;      // after the horizontal filter
  vtkSmartPointer<vtkTextureObject> Map;       // after the vertical filter: what the scene looks up
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Filter;
  int Width = 0;
  int Height = 0;

  void Release(vtkWindow* window) {
    for (vtkTextureObject* texture : {Raw.Get(), RawDepth.Get(), Half.Get(), Map.Get()})
      if (texture) texture->ReleaseGraphicsResources(window);
    if (Framebuffer) Framebuffer->ReleaseGraphicsResources(window);
    if (Filter) Filter->ReleaseGraphicsResources(window);
    Raw = RawDepth = Half = Map = nullptr;
    Framebuffer = nullptr;
    Filter.reset();
    Width = Height = 0;
  }
};

namespace {

vtkSmartPointer<vtkTextureObject> floatTexture(vtkOpenGLRenderWindow* window, int width, int height) {
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetFormat(GL_RGBA);
  texture->SetInternalFormat(GL_RGBA32F);  // depth needs more than half floats
  texture->SetDataType(GL_FLOAT);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Allocate2D(width, height, 4, VTK_FLOAT);
  return texture;
}

// A visible actor with a mapper and an importance above 0.
bool isInterest(vtkProp* prop) {
  auto* actor = vtkActor::SafeDownCast(prop);
  return actor && actor->GetVisibility() && actor->GetMapper() &&
         vtkMedialGhostPass::GetImportance(prop) > 0.0;
}

// Window pixels covered by the projected bounding boxes of the objects of interest, grown by `margin`
// (min x, min y, max x, max y); the whole viewport when a box reaches behind the camera. Fragments outside
// skip the map lookup.
void interestRectangle(vtkRenderer* renderer, const std::vector<vtkProp*>& props, const int viewport[4],
                       double margin, float rect[4]) {
  const float whole[4] = {static_cast<float>(viewport[0]), static_cast<float>(viewport[1]),
                          static_cast<float>(viewport[0] + viewport[2]),
                          static_cast<float>(viewport[1] + viewport[3])};
  std::copy(whole, whole + 4, rect);
  vtkMatrix4x4* projection = renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
      renderer->GetTiledAspectRatio(), -1, 1);
  double low[2] = {1e300, 1e300}, high[2] = {-1e300, -1e300};
  for (vtkProp* prop : props) {
    if (!isInterest(prop)) continue;
    const double* bounds = prop->GetBounds();
    if (!bounds || !(bounds[0] <= bounds[1])) continue;
    for (int corner = 0; corner < 8; ++corner) {
      const double world[4] = {bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)],
                               bounds[4 + ((corner >> 2) & 1)], 1};
      double clip[4];
      projection->MultiplyPoint(world, clip);
      if (clip[3] <= 1e-12) return;  // behind the eye: the projection folds over, keep the whole viewport
      for (int axis = 0; axis < 2; ++axis) {
        const double pixel = viewport[axis] + (clip[axis] / clip[3] + 1.0) * 0.5 * viewport[2 + axis];
        low[axis] = std::min(low[axis], pixel);
        high[axis] = std::max(high[axis], pixel);
      }
    }
  }
  if (!(low[0] <= high[0])) return;
  for (int axis = 0; axis < 2; ++axis) {
    rect[axis] = static_cast<float>(std::max<double>(whole[axis], low[axis] - margin));
    rect[2 + axis] = static_cast<float>(std::min<double>(whole[2 + axis], high[axis] + margin));
  }
}

}  // namespace

vtkMedialGhostPass::vtkMedialGhostPass() : Gpu(std::make_unique<Resources>()) {}

vtkMedialGhostPass::~vtkMedialGhostPass() = default;

void vtkMedialGhostPass::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  static const char* const modes[] = {"Off", "Ghost", "Cutaway"};
  static const char* const conflicts[] = {"DepthSorting", "GradualImportance"};
  static const char* const translucencies[] = {"Blended", "DepthPeeling", "OrderIndependent"};
  os << indent << "Mode: " << modes[this->Mode] << "\n";
  os << indent << "GhostOpacity: " << this->GhostOpacity << "\n";
  os << indent << "SilhouetteStrength: " << this->SilhouetteStrength << "\n";
  os << indent << "Conflict: " << conflicts[this->Conflict] << "\n";
  os << indent << "MapScale: " << this->MapScale << "\n";
  os << indent << "BorderWidth: " << this->BorderWidth << "\n";
  os << indent << "Translucency: " << translucencies[this->Translucency] << "\n";
  os << indent << "LayeredGhosts: " << this->LayeredGhosts << "\n";
  os << indent << "DelegatePass: " << (this->UserDelegate ? this->UserDelegate->GetClassName() : "(default)")
     << "\n";
}

void vtkMedialGhostPass::SetImportance(vtkProp* prop, double importance) {
  if (!prop) return;
  importance = std::clamp(std::isfinite(importance) ? importance : 0.0, 0.0, 1.0);
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!keys) {
    if (importance == 0.0) return;
    auto created = vtkSmartPointer<vtkInformation>::New();
    prop->SetPropertyKeys(created);
    keys = created;
  }
  if (importance == 0.0)
    keys->Remove(IMPORTANCE());
  else
    keys->Set(IMPORTANCE(), importance);
  prop->Modified();
}

double vtkMedialGhostPass::GetImportance(vtkProp* prop) {
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys && keys->Has(IMPORTANCE()) ? keys->Get(IMPORTANCE()) : 0.0;
}

void vtkMedialGhostPass::SetLayeredGhosts(bool layered) {
  if (this->LayeredGhosts == layered) return;
  this->LayeredGhosts = layered;
  this->ShaderStageTime.Modified();
  this->Modified();
}

vtkMTimeType vtkMedialGhostPass::GetShaderStageMTime() { return this->ShaderStageTime.GetMTime(); }

void vtkMedialGhostPass::SetDelegatePass(vtkRenderPass* pass) {
  if (this->UserDelegate == pass) return;
  this->UserDelegate = pass;
  this->Modified();
}

vtkRenderPass* vtkMedialGhostPass::GetDelegatePass() { return this->ActiveDelegate(this->Translucency); }

vtkRenderPass* vtkMedialGhostPass::ActiveDelegate(int translucency) {
  if (this->UserDelegate) return this->UserDelegate;
  if (!this->DefaultDelegate || this->DefaultDelegateTranslucency != translucency) {
    auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
    auto translucent = vtkSmartPointer<vtkTranslucentPass>::New();
    if (translucency == DepthPeeling) {
      auto peeling = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
      peeling->SetTranslucentPass(translucent);
      steps->SetTranslucentPass(peeling);
    } else if (translucency == OrderIndependent) {
      auto oit = vtkSmartPointer<vtkOrderIndependentTranslucentPass>::New();
      oit->SetTranslucentPass(translucent);
      steps->SetTranslucentPass(oit);
    }
    this->DefaultDelegate = steps;
    this->DefaultDelegateTranslucency = translucency;
  }
  return this->DefaultDelegate;
}

void vtkMedialGhostPass::ReleaseGraphicsResources(vtkWindow* window) {
  this->Gpu->Release(window);
  if (this->UserDelegate) this->UserDelegate->ReleaseGraphicsResources(window);
  if (this->DefaultDelegate) this->DefaultDelegate->ReleaseGraphicsResources(window);
}

void vtkMedialGhostPass::Render(const vtkRenderState* s) {
  this->NumberOfRenderedProps = 0;
  this->LastInterestCount = 0;
  this->LastMapSize[0] = this->LastMapSize[1] = 0;
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  // Dual depth peeling draws nothing translucent into a multisampled window: OIT takes over there.
  const bool multisampled = window && window->GetMultiSamples() > 0;
  vtkRenderPass* delegate = this->ActiveDelegate(this->Translucency == DepthPeeling && multisampled
                                                     ? static_cast<int>(OrderIndependent)
                                                     : this->Translucency);

  int width = 0, height = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &this->Viewport[0], &this->Viewport[1]);
  this->Viewport[2] = width;
  this->Viewport[3] = height;

  // Interest first, most important first: ghosted fragments of the others blend over them (§3).
  std::vector<vtkProp*> props(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
  std::stable_sort(props.begin(), props.end(),
                   [](vtkProp* a, vtkProp* b) { return GetImportance(a) > GetImportance(b); });
  std::vector<vtkProp*> interest;
  std::copy_if(props.begin(), props.end(), std::back_inserter(interest), isInterest);
  const int interestCount = static_cast<int>(interest.size());
  std::sort(interest.begin(), interest.end());
  if (interest != this->ShadedInterest) {  // props whose shaders write depth change: rebuild them
    this->ShadedInterest = interest;
    this->ShaderStageTime.Modified();
  }

  const bool plain = this->Mode == Off || interestCount == 0 || width <= 0 || height <= 0 || !window ||
                     renderer->GetSelector() != nullptr;
  if (plain) {
    if (this->KeepImportanceMap && renderer->GetSelector() == nullptr)
      this->KeptMap = nullptr;  // none this frame
    delegate->Render(s);
    this->NumberOfRenderedProps = delegate->GetNumberOfRenderedProps();
    return;
  }

  vtkRenderState sorted(renderer);
  sorted.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  sorted.SetFrameBuffer(s->GetFrameBuffer());
  this->PreRender(&sorted);  // puts this pass into every prop's keys: the mappers call us back

  interestRectangle(renderer, props, this->Viewport, this->BorderWidth + 2.0 + 1.0 / this->MapScale,
                    this->GhostRectangle);
  if (!(this->RenderImportanceMap(&sorted, window) && this->FilterImportanceMap(window))) {
    this->PostRender(&sorted);  // the error is reported; draw the scene plainly rather than nothing
    delegate->Render(&sorted);
    this->NumberOfRenderedProps = delegate->GetNumberOfRenderedProps();
    return;
  }
  this->LastInterestCount = interestCount;
  this->LastMapSize[0] = this->Gpu->Width;
  this->LastMapSize[1] = this->Gpu->Height;
  if (this->KeepImportanceMap) this->CopyImportanceMap();
  this->Gpu->Map->Activate();
  this->Phase = 2;
  delegate->Render(&sorted);
  this->NumberOfRenderedProps = delegate->GetNumberOfRenderedProps();
  this->Gpu->Map->Deactivate();
  this->Phase = 0;
  this->PostRender(&sorted);
}

void vtkMedialGhostPass::MapScissor(int scissor[4]) const {
  // The map texels under the objects of interest's projected boxes (GhostRectangle), grown by the
  // filter's reach: the only texels the scene looks up, so the only ones drawn, filtered and cleared.
  const int reach = this->FilterRadius() + 2;
  for (int axis = 0; axis < 2; ++axis) {
    const int size = axis == 0 ? this->Gpu->Width : this->Gpu->Height;
    const double scale = static_cast<double>(size) / this->Viewport[2 + axis];
    const int low =
        static_cast<int>(std::floor((this->GhostRectangle[axis] - this->Viewport[axis]) * scale)) - reach;
    const int high =
        static_cast<int>(std::ceil((this->GhostRectangle[2 + axis] - this->Viewport[axis]) * scale)) + reach;
    scissor[axis] = std::max(0, low);
    scissor[2 + axis] = std::max(0, std::min(size, high) - scissor[axis]);
  }
}

int vtkMedialGhostPass::FilterRadius() const {
  return static_cast<int>(std::lround(this->BorderWidth * this->MapScale));
}

bool vtkMedialGhostPass::RenderImportanceMap(const vtkRenderState* s, vtkOpenGLRenderWindow* window) {
  Resources& gpu = *this->Gpu;
  const int width = std::max(1, static_cast<int>(std::lround(this->Viewport[2] * this->MapScale)));
  const int height = std::max(1, static_cast<int>(std::lround(this->Viewport[3] * this->MapScale)));
  if (gpu.Width != width || gpu.Height != height || !gpu.Framebuffer) {
    for (vtkTextureObject* texture : {gpu.Raw.Get(), gpu.RawDepth.Get(), gpu.Half.Get(), gpu.Map.Get()})
      if (texture) texture->ReleaseGraphicsResources(window);
    gpu.Raw = floatTexture(window, width, height);
    gpu.Half = floatTexture(window, width, height);
    gpu.Map = floatTexture(window, width, height);
    gpu.RawDepth = vtkSmartPointer<vtkTextureObject>::New();
    gpu.RawDepth->SetContext(window);
    gpu.RawDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    if (!gpu.Framebuffer) {
      gpu.Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      gpu.Framebuffer->SetContext(window);
    }
    gpu.Width = width;
    gpu.Height = height;
  }

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglScissor savedScissor(state);
  vtkOpenGLState::ScopedglClearColor savedClearColor(state);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglDepthFunc savedDepthFunc(state);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedScissorTest(state, GL_SCISSOR_TEST);

  gpu.Framebuffer->SaveCurrentBindingsAndBuffers();
  gpu.Framebuffer->Bind();
  gpu.Framebuffer->AddColorAttachment(0, gpu.Raw);
  gpu.Framebuffer->ActivateDrawBuffers(1);
  gpu.Framebuffer->AddDepthAttachment(gpu.RawDepth);
  const bool complete = gpu.Framebuffer->StartNonOrtho(width, height);
  if (complete) {
    state->vtkglViewport(0, 0, width, height);
    int scissor[4];
    this->MapScissor(scissor);
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglScissor(scissor[0], scissor[1], scissor[2], scissor[3]);
    state->vtkglClearColor(0, 0, 0, 0);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDisable(GL_BLEND);

    this->Phase = 1;
    vtkRenderer* renderer = s->GetRenderer();
    for (int i = 0; i < s->GetPropArrayCount(); ++i) {
      vtkProp* prop = s->GetPropArray()[i];
      if (!isInterest(prop)) continue;
      // Drawn whatever its own opacity: a translucent object of interest still owns its pixels.
      auto* actor = vtkActor::SafeDownCast(prop);
      actor->GetProperty()->Render(actor, renderer);
      actor->Render(renderer, actor->GetMapper());
      actor->GetProperty()->PostRender(actor, renderer);
    }
    this->Phase = 0;
  }
  gpu.Framebuffer->RemoveDepthAttachment();
  gpu.Framebuffer->UnBind();
  gpu.Framebuffer->RestorePreviousBindingsAndBuffers();
  if (!complete) vtkErrorMacro(<< "cannot draw the importance map: incomplete framebuffer");
  return complete;
}

bool vtkMedialGhostPass::FilterImportanceMap(vtkOpenGLRenderWindow* window) {
  Resources& gpu = *this->Gpu;
  if (!gpu.Filter) {
    const std::string fragment = medial::ghost::mapFilterFragmentShader();
    gpu.Filter = std::make_unique<vtkOpenGLQuadHelper>(
        window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fragment.c_str(), "");
  } else {
    window->GetShaderCache()->ReadyShaderProgram(gpu.Filter->Program);
  }
  vtkShaderProgram* program = gpu.Filter->Program;
  if (!program || !program->GetCompiled()) {
    vtkErrorMacro(<< "cannot build the importance-map filter shader");
    return false;
  }

  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglScissor savedScissor(state);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedBlend(state, GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);

  // The border is given in viewport pixels; the map is MapScale of it. Only the texels under the
  // objects of interest's projected boxes are filtered (MapScissor); no others are ever looked up.
  const int radius = this->FilterRadius();
  int scissor[4];
  this->MapScissor(scissor);
  vtkOpenGLState::ScopedglEnableDisable savedScissorTest(state, GL_SCISSOR_TEST);
  const struct {
    vtkTextureObject* from;
    vtkTextureObject* to;
    int direction[2];
  } steps[] = {{gpu.Raw, gpu.Half, {1, 0}}, {gpu.Half, gpu.Map, {0, 1}}};
  bool complete = true;
  for (const auto& step : steps) {
    gpu.Framebuffer->SaveCurrentBindingsAndBuffers();
    gpu.Framebuffer->Bind();
    gpu.Framebuffer->AddColorAttachment(0, step.to);
    gpu.Framebuffer->ActivateDrawBuffers(1);
    complete = gpu.Framebuffer->StartNonOrtho(gpu.Width, gpu.Height) && complete;
    if (complete) {
      state->vtkglViewport(0, 0, gpu.Width, gpu.Height);
      state->vtkglEnable(GL_SCISSOR_TEST);
      state->vtkglScissor(scissor[0], scissor[1], scissor[2], scissor[3]);
      step.from->Activate();
      program->SetUniformi("source", step.from->GetTextureUnit());
      program->SetUniform2i("direction", step.direction);
      program->SetUniformi("radius", radius);
      gpu.Filter->Render();
      step.from->Deactivate();
    }
    gpu.Framebuffer->UnBind();
    gpu.Framebuffer->RestorePreviousBindingsAndBuffers();
  }
  if (!complete) vtkErrorMacro(<< "cannot filter the importance map: incomplete framebuffer");
  return complete;
}

bool vtkMedialGhostPass::PreReplaceShaderValues(std::string&, std::string&, std::string& fragmentShader,
                                                vtkAbstractMapper*, vtkProp*) {
  // Only VTK's polydata fragment template (polydata, glyph, sphere and image-slice mappers) has both tags.
  if (fragmentShader.find("//VTK::TCoord::Impl") == std::string::npos ||
      fragmentShader.find("//VTK::Output::Dec") == std::string::npos)
    return true;
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec",
                               std::string("//VTK::Output::Dec\n") + medial::ghost::kFragmentDeclarations);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::TCoord::Impl",
                               std::string("//VTK::TCoord::Impl\n  ") + medial::ghost::kImplementationTag);
  return true;
}

bool vtkMedialGhostPass::PostReplaceShaderValues(std::string&, std::string&, std::string& fragmentShader,
                                                 vtkAbstractMapper*, vtkProp* prop) {
  if (medial::ghost::ghostVolumeShader(fragmentShader)) return true;  // a CT volume as context
  if (fragmentShader.find(medial::ghost::kImplementationTag) == std::string::npos) return true;
  const bool withSilhouette = fragmentShader.find("normalVCVSOutput") != std::string::npos;
  // Objects of interest write depth (gradual importance orders the map by it); context props only
  // with LayeredGhosts: a shader that writes depth loses early depth testing. VTK's template mentions
  // gl_FragDepth in a comment; only an assignment means it is already written.
  const bool writesDepth = (this->LayeredGhosts || isInterest(prop)) &&
                           fragmentShader.find("gl_FragDepth =") == std::string::npos &&
                           fragmentShader.find("gl_FragDepth=") == std::string::npos;
  vtkShaderProgram::Substitute(
      fragmentShader, medial::ghost::kImplementationTag,
      medial::ghost::fragmentImplementation(withSilhouette, writesDepth, isInterest(prop)));
  return true;
}

bool vtkMedialGhostPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop,
                                             vtkOpenGLVertexArrayObject*) {
  if (!program->IsUniformUsed("medialGhostPhase")) return true;
  const double importance = isInterest(prop) ? GetImportance(prop) : 0.0;
  program->SetUniformi("medialGhostPhase", this->Phase);
  program->SetUniformf("medialGhostImportance", static_cast<float>(importance));
  if (program->IsUniformUsed("medialGhostGradual"))
    program->SetUniformi("medialGhostGradual", this->Conflict == GradualImportance ? 1 : 0);
  if (this->Phase != 2) return true;

  const bool cutaway = this->Mode == Cutaway;
  const float viewport[4] = {static_cast<float>(this->Viewport[0]), static_cast<float>(this->Viewport[1]),
                             static_cast<float>(this->Viewport[2]), static_cast<float>(this->Viewport[3])};
  program->SetUniformi("medialGhostMap", this->Gpu->Map->GetTextureUnit());
  program->SetUniform4f("medialGhostViewport", viewport);
  program->SetUniform4f("medialGhostRect", this->GhostRectangle);
  program->SetUniformf("medialGhostOpacity", cutaway ? 0.0f : static_cast<float>(this->GhostOpacity));
  if (program->IsUniformUsed("medialGhostSilhouette"))
    program->SetUniformf("medialGhostSilhouette",
                         cutaway ? 0.0f : static_cast<float>(this->SilhouetteStrength));
  if (program->IsUniformUsed("medialGhostWriteDepth"))
    program->SetUniformi("medialGhostWriteDepth",
                         prop && prop->IsRenderingTranslucentPolygonalGeometry() ? 0 : 1);
  return true;
}

vtkImageData* vtkMedialGhostPass::GetImportanceMap() {
  if (!this->KeptMap) this->KeptMap = vtkSmartPointer<vtkImageData>::New();
  return this->KeptMap;
}

void vtkMedialGhostPass::CopyImportanceMap() {
  // The map texture back from the GPU; texels outside the scissor were not drawn this frame (they may
  // hold an earlier frame's values), so they are cleared here as the scene never looks them up.
  const int width = this->Gpu->Width, height = this->Gpu->Height;
  std::vector<float> texels(size_t(width) * size_t(height) * 4, 0.0f);
  vtkPixelBufferObject* buffer = this->Gpu->Map->Download();
  if (!buffer) return;
  unsigned int dims[2] = {unsigned(width), unsigned(height)};
  vtkIdType increments[2] = {0, 0};
  const bool read = buffer->Download2D(VTK_FLOAT, texels.data(), dims, 4, increments);
  buffer->Delete();
  if (!read) return;
  int scissor[4];
  this->MapScissor(scissor);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName("ImportanceMap");
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(vtkIdType(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool drawn =
          x >= scissor[0] && x < scissor[0] + scissor[2] && y >= scissor[1] && y < scissor[1] + scissor[3];
      const float* t = &texels[(size_t(y) * size_t(width) + size_t(x)) * 4];
      for (int c = 0; c < 3; ++c) values->SetTypedComponent(vtkIdType(y) * width + x, c, drawn ? t[c] : 0.0f);
    }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->GetPointData()->SetScalars(values);
  this->KeptMap = image;
}
