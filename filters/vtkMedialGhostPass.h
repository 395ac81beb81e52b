/// \class vtkMedialGhostPass
/// \brief Ghost views and cutaway views driven by an importance map (Luboschik and Schumann, "Discovering the
/// Covered: Ghost-Views in Information Visualization", WSCG 2008): objects of interest
/// stay visible through whatever hides them.
///
/// Each prop carries an importance in [0, 1] (SetImportance, or the IMPORTANCE() key of its property keys);
/// 0 is context, above 0 an object of interest. Every frame, view-dependently (paper §3):
///  1. the objects of interest are rendered into an importance map, a float texture at MapScale of the
///     viewport's resolution (paper §5), holding per pixel the winning object's importance and window depth;
///     the map is then dilated and feathered by BorderWidth pixels so the ghosted region has a soft border;
///  2. the scene is rendered by the delegate pass (camera, lights, opaque, translucent, overlay); a fragment
///     shader added to every polygonal mapper looks the map up and, where a fragment lies in front of a more
///     important object, lowers its opacity: to GhostOpacity (Ghost mode, raised towards 1 at the occluder's
///     silhouette by SilhouetteStrength so its shape stays readable) or to 0 (Cutaway mode).
///
/// Conflicts between objects of interest (paper §3, Fig. 2): DepthSorting keeps the nearest one at each
/// pixel; GradualImportance keeps the most important one, and a less important object in front of it is
/// ghosted with an opacity that grows with its importance (mix(GhostOpacity, 1, own / map importance)).
///
/// Ghosted fragments of opaque props are blended in the opaque step over the objects of interest, which are
/// drawn first, most important first, so the objects always show; with LayeredGhosts they write the map's
/// depth, not their own, so every layer between the eye and the object shows too (no sorting among those
/// layers, as in the paper), at the price of early depth testing. Translucent
/// props keep going through the delegate's translucent step (Translucency: blended, dual depth peeling, or
/// order-independent), their alpha multiplied by the same ghost factor.
///
/// A volume rendered by VTK's GPU ray caster (composite blending; vtkMedialScene's VolumeStyle, the GUI's
/// volume rendering) is context too: over an object of interest the samples of each ray in front of it
/// may together make it only GhostOpacity opaque (0 in Cutaway mode), feathered like a fragment.
///
/// With Mode Off, no object of interest, a zero-size viewport, or during hardware selection (picking) the
/// pass renders the scene exactly like its delegate. Objects of interest must be vtkActors (assemblies,
/// volume slices and ray-cast volumes render as context).
#pragma once

#include "MedialFiltersModule.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h"

#include <memory>
#include <vector>

class vtkImageData;
class vtkInformationDoubleKey;
class vtkProp;
class vtkRenderStepsPass;
class vtkRenderer;
class vtkOpenGLRenderWindow;

class MEDIALFILTERS_EXPORT vtkMedialGhostPass : public vtkOpenGLRenderPass {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialGhostPass* New();
  vtkTypeMacro(vtkMedialGhostPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// What happens to occluders of the objects of interest: nothing, ghosted, cut away (SetMode).
  enum Modes { Off = 0, Ghost = 1, Cutaway = 2 };
  /// How overlapping objects of interest are resolved (SetConflict; the paper's two strategies).
  enum Conflicts { DepthSorting = 0, GradualImportance = 1 };
  /// How translucent ghosts are composited (SetTranslucency).
  enum Translucencies { Blended = 0, DepthPeeling = 1, OrderIndependent = 2 };

  ///@{
  /// Off, Ghost (default) or Cutaway.
  vtkSetClampMacro(Mode, int, Off, Cutaway);
  vtkGetMacro(Mode, int);
  void SetModeToOff() { this->SetMode(Off); }
  void SetModeToGhost() { this->SetMode(Ghost); }
  void SetModeToCutaway() { this->SetMode(Cutaway); }
  ///@}

  ///@{
  /// Opacity of an occluder over an object of interest in Ghost mode (default 0.25).
  vtkSetClampMacro(GhostOpacity, double, 0.0, 1.0);
  vtkGetMacro(GhostOpacity, double);
  ///@}

  ///@{
  /// How much the occluder's silhouette stays opaque in Ghost mode, 0..1 (default 0.8): the opacity rises
  /// towards 1 as (1 - |n.z|)^2, n the view-space normal, so the occluder's outline remains a shape cue.
  vtkSetClampMacro(SilhouetteStrength, double, 0.0, 1.0);
  vtkGetMacro(SilhouetteStrength, double);
  ///@}

  ///@{
  /// DepthSorting or GradualImportance (default).
  vtkSetClampMacro(Conflict, int, DepthSorting, GradualImportance);
  vtkGetMacro(Conflict, int);
  void SetConflictToDepthSorting() { this->SetConflict(DepthSorting); }
  void SetConflictToGradualImportance() { this->SetConflict(GradualImportance); }
  ///@}

  ///@{
  /// Resolution of the importance map as a fraction of the viewport's (default 0.5; paper §5: lower is
  /// faster, with a coarser border).
  vtkSetClampMacro(MapScale, double, 0.05, 1.0);
  vtkGetMacro(MapScale, double);
  ///@}

  ///@{
  /// Width in viewport pixels of the soft border around the importance map (default 2; 0 = hard edge).
  vtkSetClampMacro(BorderWidth, int, 0, 64);
  vtkGetMacro(BorderWidth, int);
  ///@}

  ///@{
  /// How the delegate composites translucent props: Blended (plain alpha blending, the renderer's
  /// default), DepthPeeling (dual depth peeling; in a multisampled window, where it would draw no
  /// translucent prop at all, OrderIndependent is used instead) or OrderIndependent (weighted blended
  /// OIT). Default Blended. Ignored when a delegate is set.
  vtkSetClampMacro(Translucency, int, Blended, OrderIndependent);
  vtkGetMacro(Translucency, int);
  ///@}

  ///@{
  /// Whether every occluding layer in front of an object of interest shows (default off). On: a ghosted
  /// fragment of an opaque prop writes the importance map's depth instead of its own, so layers behind
  /// it but still in front of the object are drawn too (unsorted, as in the paper). That makes every
  /// opaque prop's shader write gl_FragDepth, which turns off early depth testing: on this machine's
  /// software OpenGL it costs about a fifth of a frame (medial_bench_ghost). Off: a ghosted fragment
  /// keeps its own depth, so where two occluding layers overlap in front of the object, the one drawn
  /// second shows only if it is the nearer; the object itself always shows (it is drawn first).
  void SetLayeredGhosts(bool layered);
  vtkGetMacro(LayeredGhosts, bool);
  vtkBooleanMacro(LayeredGhosts, bool);
  ///@}

  ///@{
  /// The pass that renders the scene (default: a vtkRenderStepsPass built for Translucency).
  void SetDelegatePass(vtkRenderPass* pass);
  vtkRenderPass* GetDelegatePass();
  ///@}

  ///@{
  /// Importance of a prop, 0..1 (stored in its property keys; 0 removes it).
  static void SetImportance(vtkProp* prop, double importance);
  static double GetImportance(vtkProp* prop);
  static vtkInformationDoubleKey* IMPORTANCE();
  ///@}

  ///@{
  /// Keep a copy of each frame's importance map on the CPU (default off: a read-back from the GPU).
  vtkSetMacro(KeepImportanceMap, bool);
  vtkGetMacro(KeepImportanceMap, bool);
  vtkBooleanMacro(KeepImportanceMap, bool);
  ///@}
  /// The last frame's importance map (the paper's Figs. 2, 4, 6), with KeepImportanceMap: an image of the
  /// map's size (MapScale of the viewport's), float point data `ImportanceMap` with three components per
  /// pixel: the winning object's importance, its window depth, and the feathered coverage (0..1; 0 where
  /// no object of interest projects). Empty before such a frame or when the frame had no object of
  /// interest.
  vtkImageData* GetImportanceMap();

  ///@{
  /// What the last frame did: objects of interest drawn into the map, and the map's size.
  vtkGetMacro(LastInterestCount, int);
  vtkGetVector2Macro(LastMapSize, int);
  ///@}

  ///@{
  /// vtkOpenGLRenderPass: renders the delegate pass with the importance map, and injects the ghosting into
  /// the props' shaders.
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
                              std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
                               std::string& fragmentShader, vtkAbstractMapper* mapper,
                               vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
                           vtkOpenGLVertexArrayObject* vao = nullptr) override;
  ///@}
  /// Changes when a prop's shader must be rebuilt: LayeredGhosts, or the set of objects of interest
  /// changed (their shaders write depth, context props' only with LayeredGhosts).
  vtkMTimeType GetShaderStageMTime() override;

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialGhostPass();
  ~vtkMedialGhostPass() override;
  ///@}

 private:
  vtkMedialGhostPass(const vtkMedialGhostPass&) = delete;
  void operator=(const vtkMedialGhostPass&) = delete;

  vtkRenderPass* ActiveDelegate(int translucency);
  bool RenderImportanceMap(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
  bool FilterImportanceMap(vtkOpenGLRenderWindow* window);
  int FilterRadius() const;
  void MapScissor(int scissor[4]) const;

  int Mode = Ghost;
  double GhostOpacity = 0.25;
  double SilhouetteStrength = 0.8;
  int Conflict = GradualImportance;
  double MapScale = 0.5;
  int BorderWidth = 2;
  int Translucency = Blended;
  bool LayeredGhosts = false;
  bool KeepImportanceMap = false;
  vtkSmartPointer<vtkImageData> KeptMap;
  void CopyImportanceMap();
  int LastInterestCount = 0;
  int LastMapSize[2] = {0, 0};

  vtkSmartPointer<vtkRenderPass> UserDelegate;
  vtkSmartPointer<vtkRenderStepsPass> DefaultDelegate;
  int DefaultDelegateTranslucency = -1;

  struct Resources;  ///< GPU objects: map textures, framebuffers, filter shader
  std::unique_ptr<Resources> Gpu;
  int Phase = 0;  ///< 0 idle, 1 drawing the importance map, 2 drawing the scene
  int Viewport[4] = {0, 0, 0, 0};
  float GhostRectangle[4] = {0, 0, 0, 0};  ///< window pixels where the map can matter this frame
  std::vector<vtkProp*> ShadedInterest;    ///< objects of interest when the shaders were last chosen
  vtkTimeStamp ShaderStageTime;
};
