// Camera matrices of a frame and the reprojection matrices the resolve shader needs
// (glsl/camera_reprojection.glsl). All matrices here use GLM's column-vector convention; the
// EXR header's row-vector matrices are transposed on load (io/frame_reader).
#pragma once

#include <glm/mat4x4.hpp>

namespace taa {

// How a renderer's normalized device coordinates cover the display window.
enum class NdcConvention {
  ZeroOneYDown,    // x, y in [0, 1], (0, 0) at the top-left corner (RenderMan's NDC)
  MinusOneOneYUp,  // x, y in [-1, 1], y up (OpenGL's NDC)
};

struct FrameCamera {
  glm::dmat4 worldToCamera{1.0};  // to a left-handed camera space looking down +z
  glm::dmat4 worldToNdc{1.0};     // to homogeneous NDC (divide by w)
};

// Where the image's pixels sit in the display window the NDC refers to.
struct RasterWindow {
  int dataX = 0, dataY = 0;                  // data window origin minus display window origin
  int displayWidth = 0, displayHeight = 0;   // display window size
};

struct ReprojectionMatrices {
  glm::mat4 rasterToCamera;          // (raster x, raster y, ndc z, 1) -> homogeneous camera space
  glm::mat4 cameraToPreviousRaster;  // camera space -> previous (raster x, raster y, ndc z, w)
  glm::mat4 cameraToPreviousCamera;  // camera space -> previous camera space
};

// Affine map from raster (data window pixels, y down, z passed through) to NDC.
glm::dmat4 ndcFromRaster(const RasterWindow& window, NdcConvention convention);

ReprojectionMatrices reprojectionMatrices(const FrameCamera& current, const FrameCamera& previous,
                                          const RasterWindow& window, NdcConvention convention);

// A frame's raster positions carried to another frame's raster (or camera) as matrices cheap to
// apply per sample: the camera-space point a raster position (x, y) sees at planar depth d is
// d A (x, y, 1) + G (x, y, 1) for pinhole (G = 0) and orthographic cameras alike, so the
// other frame's homogeneous position is d alongDepth (x, y, 1, 0) + offset (x, y, 1, 1), and
// at infinite depth (a direction) alongDepth (x, y, 1, 0) alone. glsl/camera_geometry.glsl's
// carried() applies the rows a raster position needs (x, y, w; the window gather's uniforms).
struct CarryMatrices {
  glm::mat4 alongDepth{0.0f};
  glm::mat4 offset{0.0f};
};

// From raster positions of `from` (at their planar depth) to raster positions of `to`
// (x, y, ndc z, w), and to `to`'s camera space (toCamera: row z gives the planar depth there).
struct FrameCarry {
  CarryMatrices toRaster;
  CarryMatrices toCamera;
};
// `from`'s offsets are exactly zero when it is a pinhole camera (isPinhole): its rays meet at
// its origin, which the sums that find G would leave as rounding noise.
FrameCarry frameCarry(const FrameCamera& from, const FrameCamera& to, const RasterWindow& window,
                      NdcConvention convention);

// Whether every ray of `camera` starts at its origin (G = 0 above: perspective, not
// orthographic): the carries from it have offsets whose x and y columns are zero, which the
// window gather's pinhole variant leaves out.
bool isPinhole(const FrameCamera& camera, const RasterWindow& window, NdcConvention convention);

// The motion (pixels, y down, to the previous frame) of a static surface seen at raster
// position (x, y) at planar depth `depth`: the CPU twin of cameraMotion() in the shader.
glm::dvec2 cameraMotion(const FrameCamera& current, const FrameCamera& previous,
                        const RasterWindow& window, NdcConvention convention, glm::dvec2 position,
                        double depth);

}  // namespace taa
