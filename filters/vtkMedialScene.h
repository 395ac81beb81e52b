/// \class vtkMedialScene
/// \brief Builds what Medial shows for a data object: meshes as smoothly shaded surfaces (their own RGB
/// colours when they have them), skeletons as tubes and spheres from `Radius`, volumes as three orthogonal
/// slices with an outline. One scene serves `medial render`, the GUI and Python, so they look alike.
///
/// Colours follow the order of AddData (a palette of ivory, red, blue, green...). The default camera is a
/// three-quarter view from the front (+Z towards the viewer, +Y up, 30° azimuth, 20° elevation) that fits
/// everything; lights come from a vtkLightKit. RenderToImage renders offscreen (needs an X display; see
/// `medial render` for the private Xvfb) and writes a PNG atomically.
#pragma once

#include "MedialFiltersModule.h"
#include "vtkObject.h"
#include "vtkSmartPointer.h"

class vtkDataObject;
class vtkPolyData;
class vtkImageData;
class vtkMedialGhostPass;
class vtkProp;
class vtkProp3D;
class vtkRenderer;

class MEDIALFILTERS_EXPORT vtkMedialScene : public vtkObject {
 public:
  ///@{
  /// VTK's object protocol: New() makes an instance with the defaults, PrintSelf() prints every property.
  static vtkMedialScene* New();
  vtkTypeMacro(vtkMedialScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// The renderer the scene's props go into (made on first use).
  vtkRenderer* GetRenderer();

  /// Adds a mesh, skeleton or volume and returns its prop (an actor, or an assembly for volumes), or
  /// null for data it cannot show (an error is reported).
  vtkProp3D* AddData(vtkDataObject* data);
  /// Adds the lines of `polyData` drawn as plain lines of `width` pixels, unlit, in `rgb` (a centerline:
  /// the fly-through's camera stands on it, and it builds no geometry however many points it has).
  vtkProp3D* AddLine(vtkPolyData* polyData, const double rgb[3], double width);
  /// Removes every prop added so far.
  void Clear();

  ///@{
  /// Scale applied to `Radius` when drawing skeleton tubes (default 1: the node spheres themselves).
  vtkSetMacro(SkeletonRadiusScale, double);
  vtkGetMacro(SkeletonRadiusScale, double);
  ///@}

  ///@{
  /// How volumes added after this call are drawn: 0 three orthogonal slices with an outline (default),
  /// else a ray-cast volume rendering with a preset: 1 CT bone, 2 CT soft tissue and skin, 3 the image's
  /// full range (MedialVolumeRendering). A volume rendering is context to the ghost pass: it is ghosted
  /// or cut away in front of objects of interest like any occluder.
  vtkSetClampMacro(VolumeStyle, int, 0, 3);
  vtkGetMacro(VolumeStyle, int);
  ///@}

  ///@{
  /// Opacity of meshes added after this call (default 1). Below 1 a mesh shows what lies inside it
  /// (a skeleton, a centerline); translucency is sorted by depth peeling.
  vtkSetClampMacro(MeshOpacity, double, 0.0, 1.0);
  vtkGetMacro(MeshOpacity, double);
  ///@}

  /// The ghost-view pass (vtkMedialGhostPass) of this scene's renderer, installed on first use: objects
  /// of interest stay visible through the meshes that hide them.
  vtkMedialGhostPass* GetGhostPass();
  /// Makes a prop an object of interest (importance in (0, 1]) or context (0), and installs the pass.
  void SetImportance(vtkProp* prop, double importance);

  ///@{
  /// The default three-quarter view that fits every visible prop, for the window's aspect ratio (4:3
  /// when the renderer has no window yet).
  void ResetCamera();
  void ResetCamera(double aspect);
  ///@}
  /// A view from `azimuth` and `elevation` degrees around the front view (+Z towards the viewer).
  void ResetCamera(double aspect, double azimuth, double elevation);

  /// Renders offscreen at width x height and writes a PNG (atomically). Returns false on failure.
  bool RenderToImage(const char* fileName, int width, int height);

  /// An open X11 Display* for RenderToImage's window (vtkRenderWindow::SetDisplayId). Null (default):
  /// RenderToImage connects to $DISPLAY itself, with retries, and reports an error when it cannot (VTK
  /// alone would abort the process).
  void SetDisplayId(void* display) { this->DisplayId = display; }

  /// A skeleton is a polydata with lines and no polygons (docs/ARCHITECTURE.md §4).
  static bool IsSkeleton(vtkPolyData* polyData);

  /// RGB of palette entry i (cycles).
  static void GetPaletteColor(int i, double rgb[3]);

 protected:
  ///@{
  /// VTK's pipeline: the constructor sets the defaults; the overrides of vtkAlgorithm check the input, run
  /// the algorithm and fill the outputs (errors leave them empty).
  vtkMedialScene();
  ~vtkMedialScene() override;
  ///@}

 private:
  vtkMedialScene(const vtkMedialScene&) = delete;
  void operator=(const vtkMedialScene&) = delete;

  vtkProp3D* AddMesh(vtkPolyData* mesh, const double rgb[3]);
  vtkProp3D* AddSkeleton(vtkPolyData* skeleton, const double rgb[3]);
  vtkProp3D* AddVolume(vtkImageData* image);

  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkMedialGhostPass> GhostPass;
  int ColorIndex = 0;
  double SkeletonRadiusScale = 1.0;
  double MeshOpacity = 1.0;
  int VolumeStyle = 0;
  void* DisplayId = nullptr;
};
