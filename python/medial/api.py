"""Medial's algorithms in one call each: skeletonize, sqm, centerline, sketch, rig. Keyword arguments are
the CLI's options in snake_case; every default shown is read from a fresh filter."""
from medial import inputs
from medial.MedialFilters import (vtkMedialContractionSkeleton, vtkMedialRigWriter, vtkMedialSkinBinding,
                                  vtkMedialSketchSkeleton, vtkMedialSQM, vtkMedialTskCenterline)
from medial.errors import MedialError, run
from medial.options import Flag, Name, Number, apply_options, document
from medial.results import Centerline, Mesh, Skeleton

SKELETONIZE_OPTIONS = {
    "nodes": Number("TargetNodes"), "solver": Name("Solver"), "iterations": Number("MaxIterations"),
    "contraction_vertices": Number("ContractionVertices"), "reference_vertices": Number("ReferenceVertices"),
    "wl0": Number("InitialContractionFactor"), "sl": Number("ContractionScale"),
    "wh0": Number("InitialAttractionWeight"), "max_wl": Number("MaxContractionWeight"),
    "max_wh": Number("MaxAttractionWeight"), "shape_weight": Number("ShapeWeight"),
    "sampling_weight": Number("SamplingWeight"), "collapse_length": Number("CollapseLengthFraction"),
    "heat": Number("HeatConstant"), "refine": Flag("RefineEmbedding"), "cycle_repair": Flag("RestoreCycles"),
    "centering": Flag("CenterNodes"), "weights": Flag("ComputeWeights"),
}


@document(vtkMedialContractionSkeleton, SKELETONIZE_OPTIONS)
def skeletonize(mesh, **options):
    """Curve skeleton of a closed surface mesh by mesh contraction (Au et al. 2008, §III), as `medial
    skeleton`.

    Parameters
    ----------
    mesh : str, os.PathLike, vtkPolyData, Mesh or (V, F) arrays
        V (N, 3) coordinates, F (M, 3) vertex indices (or any polygons: they are triangulated).
    nodes : int, default {nodes}
        The skeleton's node count: exactly this many, or more where fewer would take a bone out of the
        mesh, or fewer where the curve skeleton has fewer (a MedialWarning says so). 0 keeps all.
    weights : bool, default {weights}
        Also the heat-diffusion skinning weights (§III.E): `Skeleton.weights`, (V, E).
    solver : str, default {solver}
        The sparse solver of the contraction.
    iterations : int, default {iterations}
        Most contraction iterations.
    contraction_vertices : int, default {contraction_vertices}
        A mesh with more vertices is decimated to this many before the contraction (0: never).
    reference_vertices : int, default {reference_vertices}
        A mesh of n > this many vertices starts with W_L0 x (n / reference_vertices)^1.5.
    wl0, sl, wh0 : float, defaults {wl0}, {sl}, {wh0}
        The paper's W_L0 factor, s_L and W_H0.
    max_wl, max_wh : float, defaults {max_wl}, {max_wh}
        Caps on W_L and W_H.
    shape_weight, sampling_weight : float, defaults {shape_weight}, {sampling_weight}
        w_a and w_b of the surgery's cost.
    collapse_length : float, default {collapse_length}
        delta: edges shorter than this fraction of the contracted mesh's size collapse first.
    heat : float, default {heat}
        c of the heat weights' H = c / d^2.
    refine, cycle_repair, centering : bool, defaults {refine}, {cycle_repair}, {centering}
        Embedding refinement (§III.C), putting back cycles surgery lost, moving nodes to the centroid of
        their cross-section.

    Returns
    -------
    Skeleton
        `nodes`, `edges`, `radius`, `root`; `mesh` the triangulated input with `SkeletonNode`; `weights`.

    Raises
    ------
    MedialError
        An unreadable file, a mesh without triangles, NaN coordinates, an option out of range.
    """
    surface = inputs.mesh(mesh)
    contraction = vtkMedialContractionSkeleton()
    apply_options(contraction, SKELETONIZE_OPTIONS, options, "skeletonize")
    contraction.SetInputData(surface)
    notes = run(contraction, "skeletonize")
    return Skeleton(contraction.GetOutput(0), contraction.GetOutput(1), notes)


SQM_OPTIONS = {
    "smoothing": Name("Smoothing"), "pairing": Name("Pairing"), "ring_vertices": Number("LinearRingVertices"),
    "subdivide": Number("SubdivisionLevels"), "sharp_scale": Number("SharpMinimumScale", turn_on="SharpScaling"),
    "capsule": Flag("Capsules"), "capsule_steps": Number("CapsuleSteps"),
    "triangle_fans": Flag("PairTriangles", inverted=True), "fold_repair": Flag("FoldRepair"),
    "merge": Flag("MergeNodes"), "union": Flag("Union"),
}


@document(vtkMedialSQM, SQM_OPTIONS)
def sqm(skeleton, **options):
    """Quad-dominant tube mesh of a skeleton with radii by Skeleton to Quad-dominant Mesh (SQM), as
    `medial sqm`.

    Parameters
    ----------
    skeleton : str, os.PathLike, Skeleton, vtkPolyData or (nodes, edges, radius)
        nodes (N, 3), edges (E, 2) node indices, radius (N,) > 0; a skeleton file (.swc .vtp ...).
    subdivide : int, default {subdivide}
        Catmull-Clark levels after the base mesh.
    smoothing : str, default {smoothing}
        The smoothing of the subdivided mesh.
    pairing : str, default {pairing}
        How the polygons of a branch node are paired.
    ring_vertices : int, default {ring_vertices}
        Vertices of a ring along a chain of nodes.
    capsule, capsule_steps : bool, int, defaults {capsule}, {capsule_steps}
        Round caps at the leaves, and their rings.
    sharp_scale : float, default {sharp_scale}
        Scale the sharp branch nodes down to this (turns sharp scaling on).
    triangle_fans, fold_repair, merge, union : bool, defaults {triangle_fans}, {fold_repair}, {merge}, {union}
        Triangle fans instead of paired quads at the branch nodes; repairing folds; merging nodes closer
        than their radii; the union of overlapping tubes.

    Returns
    -------
    Mesh
        `points`, `faces` (M, 4) with -1 for triangles' fourth corner, `is_closed()`, `SkeletonNode`.

    Raises
    ------
    MedialError
        No edges, no `Radius` or a radius that is not positive, an option out of range.
    """
    data = inputs.skeleton(skeleton)
    mesher = vtkMedialSQM()
    apply_options(mesher, SQM_OPTIONS, options, "sqm")
    mesher.SetInputData(data)
    run(mesher, "sqm")
    return Mesh(mesher.GetOutput())


CENTERLINE_OPTIONS = {
    "fill_holes": Flag("FillHoles"), "max_gap": Number("MaxGap"), "min_part_volume": Number("MinimumPartVolume"),
    "antecedent_width": Number("AntecedentWidth"), "branches": Flag("DetectBranches"),
    "centering": Number("CenteringIterations"), "sections": Flag("ComputeSections"),
    "section_spacing": Number("SectionSpacing"), "section_rays": Number("SectionRays"),
    "surface": Flag("ComputeSurface"),
}


@document(vtkMedialTskCenterline, CENTERLINE_OPTIONS)
def centerline(volume, *, spacing=None, origin=None, direction=None, label=None, threshold=None, seed=None,
               keep_border_parts=False, **options):
    """Centerline of a tubular structure in a CT or a label volume by the TSK method, as `medial
    centerline`.

    Parameters
    ----------
    volume : str, os.PathLike, vtkImageData or numpy array
        A file or DICOM folder, or an array indexed [z, y, x] (as ITK's GetArrayFromImage gives it).
    spacing, origin : 3 floats, optional
        For a numpy volume: voxel size and first voxel's position, in x, y, z order (ITK's GetSpacing and
        GetOrigin). Default 1 mm and 0.
    direction : 3x3 array, optional
        For a numpy volume: its axes as columns (ITK's GetDirection).
    label : int, optional
        Follow the voxels equal to this label.
    threshold : (low, high), optional
        Follow the voxels within [low, high] (colon air on CT: (-1024, -600)).
        With neither: automatic (a CT's air, else the non-zero voxels; a MedialWarning says which).
    seed : 3 floats, optional
        The start point (mm); default the structure's lowest end.
    keep_border_parts : bool, default False
        Keep parts touching the volume's border (dropped for a threshold).
    fill_holes : bool, default {fill_holes}
        Fill the structure's cavities.
    max_gap, min_part_volume : float, defaults {max_gap}, {min_part_volume}
        Bridge gaps up to this many mm between parts of at least this many mm^3.
    antecedent_width : float, default {antecedent_width}
        Width of the TSK antecedent Gaussians.
    branches : bool, default {branches}
        One polyline per branch (vessels, airways).
    centering : int, default {centering}
        Passes towards the centre of the perpendicular sections.
    sections : bool, default {sections}
        The virtual-colonoscopy measurements: `Centerline.sections` and `terrain`.
    section_spacing, section_rays : float, int, defaults {section_spacing}, {section_rays}
        mm between sections; rays per section.
    surface : bool, default {surface}
        The lumen's closed surface: `Centerline.surface`.

    Returns
    -------
    Centerline
        `points` (mm, the volume's world frame), `radius`, `arc_length`, `lines`, `sections`, `notes`.

    Raises
    ------
    MedialError
        Not a 3-D volume, a label no voxel has, an empty selection, a seed outside the structure.
    """
    image = inputs.volume(volume, spacing, origin, direction)
    tsk = vtkMedialTskCenterline()
    _select(tsk, label, threshold)
    if seed is not None:
        if len(tuple(seed)) != 3:
            raise MedialError("seed must be three numbers (x, y, z mm), got %r" % (seed,))
        tsk.SetSeed(*[float(s) for s in seed])
    if keep_border_parts:
        tsk.SetBorderParts(vtkMedialTskCenterline.BORDER_PARTS_KEEP)
    apply_options(tsk, CENTERLINE_OPTIONS, options, "centerline")
    tsk.SetInputData(image)
    notes = run(tsk, "centerline")
    notes += [tsk.GetNote(i) for i in range(tsk.GetNumberOfNotes())]
    computed = tsk.GetComputeSections()
    return Centerline(tsk.GetOutput(), tsk.GetOutputDataObject(1) if computed else None,
                      tsk.GetOutputDataObject(2) if computed else None,
                      tsk.GetOutputDataObject(3) if tsk.GetComputeSurface() else None, notes)


def _select(tsk, label, threshold):
    if label is not None and threshold is not None:
        raise MedialError("give label or threshold, not both")
    if label is not None:
        if int(label) != label:
            raise MedialError("label must be a whole number, got %r" % (label,))
        tsk.SetLabel(int(label))
    if threshold is not None:
        low, high = (float(v) for v in threshold)
        if not low <= high:
            raise MedialError("threshold must be (low, high) with low <= high, got %r" % (threshold,))
        tsk.SetThreshold(low, high)


SKETCH_OPTIONS = {
    "simplify": Number("SimplificationThreshold"), "merge": Number("MergingThreshold"),
    "prune": Number("PruningThreshold"), "collapse": Number("CollapsingThreshold"), "unit": Number("UnitLength"),
    "thickness": Number("Thickness"), "resample": Number("ResampleStep"),
    "separate_parts": Flag("MergeParts", inverted=True), "mesh": Flag("Inflate"),
}


@document(vtkMedialSketchSkeleton, SKETCH_OPTIONS)
def sketch(strokes, **options):
    """Skeleton of a sketch by straight skeletons and BoundedDP, as `medial sketch`.

    Parameters
    ----------
    strokes : str, os.PathLike or vtkPolyData
        A sketch file (.txt: strokes and their placements).
    simplify, merge, prune, collapse : float, defaults {simplify}, {merge}, {prune}, {collapse}
        The thresholds of the four operations.
    unit, thickness, resample : float, defaults {unit}, {thickness}, {resample}
        The length unit, the inflated parts' thickness, the strokes' resampling step.
    separate_parts : bool, default {separate_parts}
        Keep the parts' skeletons apart.
    mesh : bool, default {mesh}
        Inflate the parts into `Skeleton.mesh`.

    Returns
    -------
    Skeleton
        `nodes`, `edges`, `radius` (the inscribed balls), `mesh`.

    Raises
    ------
    MedialError
        Not a sketch (no strokes), an option out of range.
    """
    data = inputs.read(strokes) if inputs.convert.is_path(strokes) else strokes
    if not hasattr(data, "GetNumberOfLines") or data.GetNumberOfLines() == 0:
        raise MedialError("sketch: not a sketch (no strokes)")
    skeletonizer = vtkMedialSketchSkeleton()
    apply_options(skeletonizer, SKETCH_OPTIONS, options, "sketch")
    skeletonizer.SetInputData(data)
    notes = run(skeletonizer, "sketch")
    return Skeleton(skeletonizer.GetOutput(0), skeletonizer.GetOutput(1) if skeletonizer.GetInflate() else None,
                    notes)


UP_AXES = ("x", "y", "z", "-x", "-y", "-z")
RIG_OPTIONS = {"max_influences": Number("MaxInfluences"), "scale": Number("Scale")}


def rig(skeleton, mesh=None, path="rig.glb", *, up_axis="y", heat=None, **options):
    """Writes a rig (glTF 2.0 .glb or FBX .fbx) for Blender, Maya or a game engine, as `medial skeleton
    --rig`.

    Parameters
    ----------
    skeleton : Skeleton, str, os.PathLike, vtkPolyData or (nodes, edges, radius)
        One bone per edge, rooted at `root` (else the body centre).
    mesh : str, os.PathLike, vtkPolyData, Mesh or (V, F), optional
        The skin, bound to the skeleton by heat diffusion (§III.E). None: the skeleton's own mesh and
        weights (from skeletonize(..., weights=True)).
    path : str or os.PathLike
        The rig file.
    up_axis : str, default "y"
        The mesh's up axis (x, y, z, -x, -y, -z): z for most scans and CAD. The character stands in Blender.
    scale : float, default 1
        Mesh units to metres (0.01 for centimetres).
    max_influences : int, default 4
        Most bones per vertex.
    heat : float, optional
        c of the heat weights when the mesh is bound here.

    Returns
    -------
    str
        The path written.

    Raises
    ------
    MedialError
        No weights and no mesh, a mesh or skeleton the binding refuses, an unknown up axis, a bad scale.
    """
    writer = vtkMedialRigWriter()
    apply_options(writer, RIG_OPTIONS, options, "rig")
    if str(up_axis) not in UP_AXES:  # before the binding, which takes seconds on a large mesh
        raise MedialError("rig: up_axis must be one of %s, got %r" % (", ".join(UP_AXES), up_axis))
    skin, bones = _bind(skeleton, mesh, heat)
    writer.SetFileName(str(path))
    writer.SetUpAxis(str(up_axis))
    writer.SetInputData(0, skin)
    writer.SetSkeletonData(bones)
    run(writer, str(path), write=True)
    return str(path)


def _bind(skeleton, mesh, heat):
    """The skinned mesh and its skeleton: the Skeleton's own when no mesh is given, else a new binding."""
    if mesh is None:
        if not isinstance(skeleton, Skeleton) or skeleton.weights is None:
            raise MedialError("rig: no skinning weights: pass the mesh, or skeletonize(..., weights=True)")
        return skeleton.mesh.polydata, skeleton.polydata
    binding = vtkMedialSkinBinding()
    if heat is not None:
        Number("HeatConstant").apply(binding, "heat", heat)
    binding.SetInputData(inputs.mesh(mesh))
    binding.SetSkeletonData(inputs.skeleton(skeleton))
    run(binding, "rig")
    return binding.GetOutput(0), binding.GetOutput(1)
