#include "MedialGhostShaders.h"

#include <vtkOpenGLRenderUtilities.h>
#include <vtkShaderProgram.h>

namespace medial::ghost {

const char* const kFragmentDeclarations = R"(
// Medial ghost view (importance map, Luboschik and Schumann 2008)
uniform sampler2D medialGhostMap;    // r: importance, g: window depth, b: coverage (feathered)
uniform int medialGhostPhase;        // 1: drawing the importance map, 2: drawing the scene
uniform float medialGhostImportance; // this prop's importance
uniform float medialGhostOpacity;    // opacity over a more important object (0: cutaway)
uniform float medialGhostSilhouette; // extra opacity at the silhouette, 0..1
uniform int medialGhostGradual;      // 1: most important object wins the map, 0: nearest
uniform int medialGhostWriteDepth;   // 1: ghosted fragments write the map's depth (opaque step)
uniform vec4 medialGhostViewport;    // lower-left corner and size of the viewport, pixels
uniform vec4 medialGhostRect;        // window pixels that can be ghosted: min x, min y, max x, max y
)";

const char* const kImplementationTag = "//MEDIAL::Ghost::Impl";

std::string fragmentImplementation(bool withSilhouette, bool writesDepth, bool interest) {
  // Written without branches on per-fragment values: Mesa's llvmpipe runs both sides of such a branch
  // under a mask anyway and pays for the masking on top (medial_bench_ghost measures it).
  std::string code = R"(
  float medialDepth = gl_FragCoord.z;
)";
  if (interest)  // only objects of interest are drawn into the map
    code += R"(
  // Importance map (paper §3 step 1). Gradual importance: the depth test keeps the most important
  // object, the nearest among equals; depth sorting: the nearest.
  if (medialGhostPhase == 1)
  {
    gl_FragData[0] = vec4(medialGhostImportance, gl_FragCoord.z, 1.0, 1.0);
    medialDepth = medialGhostGradual == 1 ? (1.0 - medialGhostImportance) * 0.999 + gl_FragCoord.z * 0.001
                                          : gl_FragCoord.z;
  }
)";
  code += R"(
  // Scene (paper §3 step 2): lower the opacity in front of a more important object. One filtered
  // lookup: the map filter spreads importance and depth a texel beyond the coverage, so the bilinear
  // blend near the border stays on valid values while the coverage feathers. Outside the rectangle
  // the map may hold anything: the lookup is made, and ignored.
  vec4 medialMap = texture(medialGhostMap, (gl_FragCoord.xy - medialGhostViewport.xy) / medialGhostViewport.zw);
  bool medialGhosted = medialGhostPhase == 2 && all(greaterThanEqual(gl_FragCoord.xy, medialGhostRect.xy)) &&
                       all(lessThanEqual(gl_FragCoord.xy, medialGhostRect.zw)) && medialMap.b > 0.0 &&
                       medialMap.r > medialGhostImportance && gl_FragCoord.z < medialMap.g;
  float medialTarget = mix(medialGhostOpacity, 1.0, medialGhostImportance / max(medialMap.r, 1e-6));
)";
  if (withSilhouette)
    code += R"(
  // Outline cue on the outer surface only: the far walls seen from inside stay plain ghosts.
  float medialFacing = abs(normalize(normalVCVSOutput).z);
  medialTarget = gl_FrontFacing ? mix(medialTarget, 1.0, medialGhostSilhouette * (1.0 - medialFacing) * (1.0 - medialFacing))
                                : medialTarget;
)";
  code += R"(
  gl_FragData[0].a *= medialGhosted ? mix(1.0, medialTarget, clamp(medialMap.b, 0.0, 1.0)) : 1.0;
)";
  if (writesDepth)
    code += R"(
  medialDepth = medialGhosted && medialGhostWriteDepth == 1 ? medialMap.g : medialDepth;
  gl_FragDepth = medialDepth;
)";
  return code;
}

namespace {

// Where VTK 9.1's raycasterfs.glsl, expanded for composite blending, starts marching and composites a
// sample (vtkVolumeShaderComposer.h).
const char* const kRayStart = "g_currentT = 0.0;";
const char* const kSampleComposite = "g_srcColor.rgb *= g_srcColor.a;";

const char* const kVolumeStart = R"(g_currentT = 0.0;
  // Medial ghost view: the importance map at this pixel gives how much, and up to which step of the ray.
  // Over the object of interest (full coverage) the whole ray: it ends at the object, or at an opaque
  // prop in front of it (the depth buffer). In the feathered border, up to the map's depth (the nearest
  // object depth around), carried back along the ray like VTK's depth-buffer termination.
  if (medialGhostPhase == 2 && all(greaterThanEqual(gl_FragCoord.xy, medialGhostRect.xy)) &&
      all(lessThanEqual(gl_FragCoord.xy, medialGhostRect.zw)))
  {
    vec4 medialMap = texture(medialGhostMap, (gl_FragCoord.xy - medialGhostViewport.xy) / medialGhostViewport.zw);
    if (medialMap.b > 0.0 && medialMap.r > medialGhostImportance)
    {
      medialGhostCap = mix(1.0, mix(medialGhostOpacity, 1.0, medialGhostImportance / medialMap.r),
                           clamp(medialMap.b, 0.0, 1.0));
      vec4 medialEnd = WindowToNDC(gl_FragCoord.x, gl_FragCoord.y, medialMap.g);
      medialEnd = ip_inverseTextureDataAdjusted * in_inverseVolumeMatrix[0] * in_inverseModelViewMatrix *
                  in_inverseProjectionMatrix * medialEnd;
      medialGhostSteps = medialMap.b >= 1.0 ? g_terminatePointMax + 1.0
                                            : length(medialEnd.xyz / medialEnd.w - g_dataPos.xyz) / length(g_dirStep);
    }
  }
)";

// In front of the object, a sample adds only what keeps the ray's opacity within the cap.
const char* const kVolumeSample = R"(if (g_currentT < medialGhostSteps)
          g_srcColor.a = min(g_srcColor.a, max(0.0, (medialGhostCap - g_fragColor.a) / max(1.0 - g_fragColor.a, 1e-6)));
        g_srcColor.rgb *= g_srcColor.a;)";

}  // namespace

bool ghostVolumeShader(std::string& fragmentShader) {
  if (fragmentShader.find("castRay(") == std::string::npos ||
      fragmentShader.find("//VTK::Output::Dec") == std::string::npos ||
      fragmentShader.find(kRayStart) == std::string::npos ||
      fragmentShader.find(kSampleComposite) == std::string::npos)
    return false;
  vtkShaderProgram::Substitute(
      fragmentShader, "//VTK::Output::Dec",
      std::string("//VTK::Output::Dec\n") + kFragmentDeclarations +
          "float medialGhostCap = 1.0;     // the ray's opacity in front of the object\n"
          "float medialGhostSteps = -1.0;  // up to this step\n");
  vtkShaderProgram::Substitute(fragmentShader, kRayStart, kVolumeStart);
  vtkShaderProgram::Substitute(fragmentShader, kSampleComposite, kVolumeSample);
  return true;
}

std::string mapFilterFragmentShader() {
  std::string source = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(source, "//VTK::FSQ::Decl",
                               "uniform sampler2D source;\n"
                               "uniform ivec2 direction;\n"
                               "uniform int radius;\n");
  vtkShaderProgram::Substitute(source, "//VTK::FSQ::Impl", R"(
  ivec2 size = textureSize(source, 0);
  ivec2 p = ivec2(texCoord * vec2(size));  // texCoord (not gl_FragCoord): the quad needs its attribute used
  float importance = 0.0;
  float depth = 1.0;
  float coverage = 0.0;
  int reach = radius + 1;
  for (int i = -reach; i <= reach; ++i)
  {
    vec4 s = texelFetch(source, clamp(p + i * direction, ivec2(0), size - ivec2(1)), 0);
    if (s.r > 0.0)
    {
      depth = min(depth, s.g);
      importance = max(importance, s.r);
      // Linear ramp from 1 at the object to 1 / (radius + 1) at the border's outer edge, 0 beyond.
      coverage = max(coverage, s.b * float(max(radius + 1 - abs(i), 0)) / float(radius + 1));
    }
  }
  gl_FragData[0] = vec4(importance, depth, coverage, 1.0);
)");
  return source;
}

}  // namespace medial::ghost
