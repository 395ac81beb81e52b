/// \file
/// GLSL pieces of vtkMedialGhostPass: the code added to VTK's polydata fragment shader, and the
/// separable filter that dilates and feathers the importance map.
#pragma once

#include <string>

namespace medial::ghost {

/// Declarations inserted before the tag \c //VTK::%Output::%Dec.
extern const char* const kFragmentDeclarations;

/// Tag placed after \c //VTK::%TCoord::%Impl (the fragment's final colour) before VTK's own substitutions,
/// replaced by fragmentImplementation() after them.
extern const char* const kImplementationTag;

/// The per-fragment code. `withSilhouette`: the shader has a view-space normal (normalVCVSOutput);
/// `writesDepth`: the shader does not already write gl_FragDepth, so this code may; `interest`: the prop
/// is an object of interest, also drawn into the importance map.
std::string fragmentImplementation(bool withSilhouette, bool writesDepth, bool interest);

/// VTK's GPU ray caster (vtkOpenGLGPUVolumeRayCastMapper, composite blending) as context: where the map
/// covers a pixel, the samples of the ray in front of the object of interest may together make it only as
/// opaque as a ghosted occluder's fragment (ghost: GhostOpacity, feathered by the coverage; cutaway: 0);
/// the samples behind it, where the border lets the ray go on, are composited as usual.
/// Returns false, leaving the shader alone, when it is not the ray caster's composite template.
bool ghostVolumeShader(std::string& fragmentShader);

/// Full-screen-quad fragment shader of one direction of the map filter (uniforms: source, direction,
/// radius). Importance: max, depth: min over radius + 1 texels (so a coarse map does not put the object of
/// interest behind its true surface, and a bilinear lookup at the border blends valid values); coverage:
/// the mask feathered over radius texels.
std::string mapFilterFragmentShader();

}  // namespace medial::ghost
