#include "color/ocio_gpu_resources.h"

#include <string>

#include "taa/error.h"

namespace taa::color {
namespace {

namespace OCIO = OCIO_NAMESPACE;

GLint filterFor(OCIO::Interpolation interpolation) {
  return interpolation == OCIO::INTERP_NEAREST ? GL_NEAREST : GL_LINEAR;
}

gl::Handle<gl::TextureDeleter> newTexture(const gl::Functions& gl, GLenum target, GLint filter) {
  GLuint id = 0;
  gl.GenTextures(1, &id);
  gl::Handle<gl::TextureDeleter> texture(&gl, id);
  gl.BindTexture(target, id);
  gl.TexParameteri(target, GL_TEXTURE_MIN_FILTER, filter);
  gl.TexParameteri(target, GL_TEXTURE_MAG_FILTER, filter);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return texture;
}

}  // namespace

OcioGpuResources::OcioGpuResources(const gl::Functions& gl, const OCIO::GpuShaderDescRcPtr& desc,
                                   int firstUnit)
    : gl_(&gl), desc_(desc), firstUnit_(firstUnit) {
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (unsigned i = 0; i < desc->getNumTextures(); ++i) {
    const char *textureName = nullptr, *samplerName = nullptr;
    unsigned width = 0, height = 0;
    OCIO::GpuShaderDesc::TextureType channel = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
    OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
    desc->getTexture(i, textureName, samplerName, width, height, channel, interpolation);
    const float* values = nullptr;
    desc->getTextureValues(i, values);
    const bool red = channel == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL;
    const GLint internalFormat = red ? GL_R32F : GL_RGB32F;
    const GLenum format = red ? GL_RED : GL_RGB;
    Lut lut;
    lut.samplerName = samplerName;
    lut.target = height > 1 ? GL_TEXTURE_2D : GL_TEXTURE_1D;
    lut.texture = newTexture(gl, lut.target, filterFor(interpolation));
    if (lut.target == GL_TEXTURE_2D) {
      gl.TexImage2D(GL_TEXTURE_2D, 0, internalFormat, GLsizei(width), GLsizei(height), 0, format,
                    GL_FLOAT, values);
    } else {
      gl.TexImage1D(GL_TEXTURE_1D, 0, internalFormat, GLsizei(width), 0, format, GL_FLOAT, values);
    }
    textures_.push_back(std::move(lut));
  }
  for (unsigned i = 0; i < desc->getNum3DTextures(); ++i) {
    const char *textureName = nullptr, *samplerName = nullptr;
    unsigned edge = 0;
    OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
    desc->get3DTexture(i, textureName, samplerName, edge, interpolation);
    const float* values = nullptr;
    desc->get3DTextureValues(i, values);
    Lut lut;
    lut.samplerName = samplerName;
    lut.target = GL_TEXTURE_3D;
    lut.texture = newTexture(gl, GL_TEXTURE_3D, filterFor(interpolation));
    gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, GLsizei(edge), GLsizei(edge), GLsizei(edge), 0,
                  GL_RGB, GL_FLOAT, values);
    textures_.push_back(std::move(lut));
  }
  gl::checkError(gl, "uploading OCIO LUT textures");
}

void OcioGpuResources::setUniforms(const gl::Program& program) const {
  if (!gl_) return;
  const gl::Functions& gl = *gl_;
  for (std::size_t i = 0; i < textures_.size(); ++i) {
    program.set(textures_[i].samplerName.c_str(), firstUnit_ + int(i));
  }
  for (unsigned i = 0; i < desc_->getNumUniforms(); ++i) {
    OCIO::GpuShaderDesc::UniformData data;
    const char* name = desc_->getUniform(i, data);
    const GLint location = gl.GetUniformLocation(program.id(), name);
    if (location < 0) continue;  // optimised away
    switch (data.m_type) {
      case OCIO::UNIFORM_DOUBLE:
        gl.ProgramUniform1f(program.id(), location, float(data.m_getDouble()));
        break;
      case OCIO::UNIFORM_BOOL:
        gl.ProgramUniform1i(program.id(), location, data.m_getBool() ? 1 : 0);
        break;
      case OCIO::UNIFORM_FLOAT3: {
        const OCIO::Float3& v = data.m_getFloat3();
        gl.ProgramUniform3f(program.id(), location, v[0], v[1], v[2]);
        break;
      }
      case OCIO::UNIFORM_VECTOR_FLOAT:
        gl.ProgramUniform1fv(program.id(), location, GLsizei(data.m_vectorFloat.m_getSize()),
                             data.m_vectorFloat.m_getVector());
        break;
      case OCIO::UNIFORM_VECTOR_INT:
        gl.ProgramUniform1iv(program.id(), location, GLsizei(data.m_vectorInt.m_getSize()),
                             data.m_vectorInt.m_getVector());
        break;
      default:
        throw Error(std::string("OCIO uniform ") + name + " has a type taa does not handle");
    }
  }
  gl::checkError(gl, "setting OCIO uniforms");
}

void OcioGpuResources::bind() const {
  if (!gl_) return;
  for (std::size_t i = 0; i < textures_.size(); ++i) {
    gl_->ActiveTexture(GL_TEXTURE0 + GLenum(firstUnit_ + int(i)));
    gl_->BindTexture(textures_[i].target, textures_[i].texture.id());
  }
}

}  // namespace taa::color
