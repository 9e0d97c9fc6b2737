// The GL side of one OCIO GPU shader: its LUT textures and uniforms, bound after taa's own
// texture units.
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <vector>

#include "gl/objects.h"

namespace taa::color {

class OcioGpuResources {
 public:
  OcioGpuResources() = default;
  // Uploads every LUT of `desc` (1D LUTs as GL_TEXTURE_1D, or 2D when OCIO folds a long one;
  // 3D LUTs as GL_TEXTURE_3D), to be bound at units firstUnit, firstUnit + 1, ...
  OcioGpuResources(const gl::Functions& gl, const OCIO_NAMESPACE::GpuShaderDescRcPtr& desc,
                   int firstUnit);

  // Texture units used, from firstUnit on.
  int unitCount() const { return int(textures_.size()); }
  // Points the program's LUT samplers at their units and sets OCIO's uniforms.
  void setUniforms(const gl::Program& program) const;
  // Binds the LUT textures to their units (before each draw: other passes share the units).
  void bind() const;

 private:
  struct Lut {
    gl::Handle<gl::TextureDeleter> texture;
    GLenum target = 0;
    std::string samplerName;
  };
  const gl::Functions* gl_ = nullptr;
  OCIO_NAMESPACE::GpuShaderDescRcPtr desc_;
  int firstUnit_ = 0;
  std::vector<Lut> textures_;
};

}  // namespace taa::color
