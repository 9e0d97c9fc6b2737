#include "gl/objects.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "gl/pass_profile.h"
#include "gl/shader_expansion.h"
#include "gl/shader_library.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

std::string hexEnum(GLenum value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04X", value);
  return text;
}

const char* glErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
  }
  return "unknown GL error";
}

std::string framebufferStatusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
  }
  return hexEnum(status);
}

// The pixel-transfer format that goes with a sized internal format.
GLenum baseFormat(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_R8: case GL_R16F: case GL_R32F: return GL_RED;
    case GL_RG8: case GL_RG16F: case GL_RG32F: return GL_RG;
    case GL_RGB8: case GL_RGB16F: case GL_RGB32F: return GL_RGB;
    case GL_RGBA8: case GL_RGBA16F: case GL_RGBA32F: return GL_RGBA;
    case GL_R32UI: return GL_RED_INTEGER;
    case GL_RGBA32UI: return GL_RGBA_INTEGER;
  }
  throw Error("unsupported texture internal format " + hexEnum(internalFormat));
}

// A pixel-transfer type `format` accepts (for an allocation without data, any it accepts).
GLenum transferTypeOf(GLenum format) {
  return format == GL_RGBA_INTEGER || format == GL_RED_INTEGER ? GL_UNSIGNED_INT : GL_FLOAT;
}

GLenum formatOfComponents(int components) {
  switch (components) {
    case 1: return GL_RED;
    case 2: return GL_RG;
    case 3: return GL_RGB;
    case 4: return GL_RGBA;
  }
  throw Error("texture upload: " + std::to_string(components) + " components per pixel " +
              "(expected 1 to 4)");
}

struct ShaderDeleter {
  void operator()(const Functions& gl, GLuint id) const { gl.DeleteShader(id); }
};

std::string shaderLog(const Functions& gl, GLuint shader) {
  GLint length = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) gl.GetShaderInfoLog(shader, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log.empty() ? "(the driver gave no log)" : log;
}

std::string programLog(const Functions& gl, GLuint program) {
  GLint length = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) gl.GetProgramInfoLog(program, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log.empty() ? "(the driver gave no log)" : log;
}

Handle<ShaderDeleter> compileShader(const Functions& gl, GLenum stage, const ShaderSource& source) {
  const char* stageName = stage == GL_VERTEX_SHADER ? "vertex" : "fragment";
  Handle<ShaderDeleter> shader(&gl, gl.CreateShader(stage));
  if (!shader) {
    checkError(gl, "glCreateShader");
    throw Error(std::string("glCreateShader failed for ") + stageName + " shader \"" +
                source.name + "\"");
  }
  const char* text = source.text.c_str();
  gl.ShaderSource(shader.id(), 1, &text, nullptr);
  gl.CompileShader(shader.id());
  GLint compiled = GL_FALSE;
  gl.GetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
  if (!compiled) {
    const std::vector<std::string> files =
        source.fileNames.empty() ? std::vector<std::string>{source.name} : source.fileNames;
    throw Error(std::string(stageName) + " shader \"" + source.name + "\" failed to compile:\n" +
                annotateShaderLog(shaderLog(gl, shader.id()), source.text, files));
  }
  return shader;
}

}  // namespace

void checkError(const Functions& gl, const char* what) {
  std::string errors;
  // Bounded: a lost context may report errors forever.
  for (int i = 0; i < 8; ++i) {
    const GLenum error = gl.GetError();
    if (error == GL_NO_ERROR) break;
    errors += (errors.empty() ? "" : ", ") + std::string(glErrorName(error));
  }
  if (!errors.empty()) throw Error(std::string("OpenGL error after ") + what + ": " + errors);
}

// --- Texture -----------------------------------------------------------------------------

Texture::Texture(const Functions& gl, int width, int height, GLenum internalFormat,
                 Filter filter)
    : width_(width), height_(height), format_(internalFormat) {
  if (width <= 0 || height <= 0) {
    throw Error("texture size " + std::to_string(width) + "x" + std::to_string(height) +
                " is not positive");
  }
  const GLenum format = baseFormat(internalFormat);
  GLuint id = 0;
  gl.GenTextures(1, &id);
  handle_ = Handle<TextureDeleter>(&gl, id);
  gl.BindTexture(GL_TEXTURE_2D, id);
  const GLint glFilter = filter == Filter::Linear ? GL_LINEAR : GL_NEAREST;
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, glFilter);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, glFilter);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);  // complete without mipmaps
  gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format,
                GL_FLOAT, nullptr);
  checkError(gl, ("creating a " + std::to_string(width) + "x" + std::to_string(height) +
                  " texture of format " + hexEnum(internalFormat)).c_str());
}

void Texture::upload(const void* pixels, int components, GLenum type) {
  if (!handle_) throw Error("texture upload: the texture was never created");
  if (!pixels) throw Error("texture upload: no pixel data");
  const GLenum format = formatOfComponents(components);
  const Functions& gl = handle_.gl();
  gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.BindTexture(GL_TEXTURE_2D, handle_.id());
  // Row 0 of `pixels` becomes texel row 0: no flip, see the class comment.
  gl.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, format, type, pixels);
  checkError(gl, "uploading a texture");
}

void Texture::bind(int unit) const {
  const Functions& gl = handle_.gl();
  gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  gl.BindTexture(GL_TEXTURE_2D, handle_.id());
}

void Texture::bindImage(int unit) const {
  const Functions& gl = handle_.gl();
  if (!gl.BindImageTexture) throw Error("texture: this OpenGL context has no image stores");
  gl.BindImageTexture(GLuint(unit), handle_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format_);
  checkError(gl, "binding a texture as an image");
}

void Texture::readRGBA(void* pixels, GLenum type) const {
  const Functions& gl = handle_.gl();
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  // The active unit's binding put back: a read between draws leaves their inputs as bound.
  GLint bound = 0;
  gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  gl.BindTexture(GL_TEXTURE_2D, handle_.id());
  gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, type, pixels);
  gl.BindTexture(GL_TEXTURE_2D, GLuint(bound));
  checkError(gl, "reading a texture back");
}

// --- TextureArray ------------------------------------------------------------------------

int largestTextureArrayLayers(const Functions& gl, int width, int height, int wanted,
                              GLenum internalFormat) {
  const GLenum format = baseFormat(internalFormat);
  const GLenum type = transferTypeOf(format);
  auto accepted = [&](int layers) {
    gl.TexImage3D(GL_PROXY_TEXTURE_2D_ARRAY, 0, static_cast<GLint>(internalFormat), width, height,
                  layers, 0, format, type, nullptr);
    GLint proxyWidth = 0;
    gl.GetTexLevelParameteriv(GL_PROXY_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_WIDTH, &proxyWidth);
    gl.GetError();  // a refused proxy may also raise an error: the width is the answer
    return proxyWidth != 0;
  };
  if (accepted(wanted)) return wanted;
  int low = 0, high = wanted;  // low accepted (0: none yet), high refused
  while (high - low > 1) {
    const int middle = low + (high - low) / 2;
    (accepted(middle) ? low : high) = middle;
  }
  return low;
}

TextureArray::TextureArray(const Functions& gl, int width, int height, int layers,
                           GLenum internalFormat)
    : width_(width), height_(height), layers_(layers) {
  if (width <= 0 || height <= 0 || layers <= 0) {
    throw Error("texture array size " + std::to_string(width) + "x" + std::to_string(height) +
                "x" + std::to_string(layers) + " is not positive");
  }
  const GLenum format = baseFormat(internalFormat);
  GLuint id = 0;
  gl.GenTextures(1, &id);
  handle_ = Handle<TextureDeleter>(&gl, id);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, id);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  const GLenum type = transferTypeOf(format);
  gl.TexImage3D(GL_TEXTURE_2D_ARRAY, 0, static_cast<GLint>(internalFormat), width, height, layers,
                0, format, type, nullptr);
  checkError(gl, ("creating a " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                  std::to_string(layers) + " texture array of format " +
                  hexEnum(internalFormat)).c_str());
}

void TextureArray::upload(int layer, const void* pixels, int components, GLenum type) {
  uploadRows(layer, 0, height_, pixels, components, type);
}

void TextureArray::uploadRows(int layer, int firstRow, int rows, const void* pixels,
                              int components, GLenum type) {
  if (!handle_) throw Error("texture array upload: the texture was never created");
  if (!pixels) throw Error("texture array upload: no pixel data");
  if (layer < 0 || layer >= layers_) throw Error("texture array upload: no layer " + std::to_string(layer));
  if (firstRow < 0 || rows < 0 || firstRow + rows > height_) {
    throw Error("texture array upload: rows " + std::to_string(firstRow) + ".." +
                std::to_string(firstRow + rows - 1) + " are not in its " +
                std::to_string(height_));
  }
  const Functions& gl = handle_.gl();
  gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, handle_.id());
  gl.TexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, firstRow, layer, width_, rows, 1,
                   formatOfComponents(components), type, pixels);
  checkError(gl, "uploading a texture array layer");
}

void TextureArray::bind(int unit) const {
  const Functions& gl = handle_.gl();
  gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  gl.BindTexture(GL_TEXTURE_2D_ARRAY, handle_.id());
}

// --- Framebuffer -------------------------------------------------------------------------

Framebuffer::Framebuffer(const Functions& gl, const Texture& colorAttachment)
    : Framebuffer(gl, std::vector<Attachment>{&colorAttachment}) {}

Framebuffer::Framebuffer(const Functions& gl, const std::vector<Attachment>& colorAttachments) {
  const auto first = std::find_if(colorAttachments.begin(), colorAttachments.end(),
                                  [](const Attachment& a) { return a.present; });
  if (first == colorAttachments.end()) throw Error("framebuffer: no colour attachment given");
  width_ = first->width;
  height_ = first->height;
  GLuint id = 0;
  gl.GenFramebuffers(1, &id);
  handle_ = Handle<FramebufferDeleter>(&gl, id);
  gl.BindFramebuffer(GL_FRAMEBUFFER, id);
  std::vector<GLenum> drawBuffers;
  for (const Attachment& texture : colorAttachments) {
    if (!texture.present) {  // nothing at this location: the shader's output there is dropped
      drawBuffers.push_back(GL_NONE);
      continue;
    }
    if (!texture.id) throw Error("framebuffer: a colour texture was never created");
    if (texture.width != width_ || texture.height != height_) {
      throw Error("framebuffer: colour attachments differ in size");
    }
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(drawBuffers.size());
    if (texture.layer >= 0) {
      gl.FramebufferTextureLayer(GL_FRAMEBUFFER, attachment, texture.id, 0, texture.layer);
    } else {
      gl.FramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture.id, 0);
    }
    drawBuffers.push_back(attachment);
  }
  // Draw and read buffers are per-framebuffer state.
  gl.DrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("framebuffer is incomplete (" + framebufferStatusName(status) + ")");
  }
  checkError(gl, "creating a framebuffer");
  attachments_ = int(drawBuffers.size());
}

void Framebuffer::bind() const {
  const Functions& gl = handle_.gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, handle_.id());
  gl.Viewport(0, 0, width_, height_);
}

std::vector<float> Framebuffer::readRGBA(int index) const {
  std::vector<float> pixels(static_cast<size_t>(width_) * static_cast<size_t>(height_) * 4);
  readRGBA(pixels.data(), GL_FLOAT, index);
  return pixels;
}

void Framebuffer::readRGBA(void* pixels, GLenum type, int index) const {
  const Functions& gl = handle_.gl();
  if (index < 0 || index >= attachments_) throw Error("framebuffer: no attachment " + std::to_string(index));
  // Straight into client memory, no pixel-pack buffer: on llvmpipe a PBO adds a copy (about
  // 9 ms CPU per 1080p frame) and overlaps nothing, the rasterizer being the CPU itself.
  gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, handle_.id());
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0 + GLenum(index));
  // Rows come back in the order GL stores them, row 0 first: no flip.
  gl.ReadPixels(0, 0, width_, height_, GL_RGBA, type, pixels);
  checkError(gl, "reading a framebuffer back");
}

// --- Program -----------------------------------------------------------------------------

ShaderSource embeddedShaderSource(const std::string& name,
                                  const std::vector<std::string>& defines) {
  ShaderSource source;
  source.name = name;
  source.text = insertAfterFirstLine(expandedShaderSource(name, &source.fileNames), defines);
  return source;
}

Program::Program(const Functions& gl, const std::string& vertexShader,
                 const std::string& fragmentShader, const std::vector<std::string>& defines)
    : Program(gl, embeddedShaderSource(vertexShader, defines),
              embeddedShaderSource(fragmentShader, defines)) {}

Program::Program(const Functions& gl, const ShaderSource& vertex, const ShaderSource& fragment) {
  Handle<ShaderDeleter> vertexShader = compileShader(gl, GL_VERTEX_SHADER, vertex);
  Handle<ShaderDeleter> fragmentShader = compileShader(gl, GL_FRAGMENT_SHADER, fragment);
  handle_ = Handle<ProgramDeleter>(&gl, gl.CreateProgram());
  if (!handle_) {
    checkError(gl, "glCreateProgram");
    throw Error("glCreateProgram failed");
  }
  gl.AttachShader(handle_.id(), vertexShader.id());
  gl.AttachShader(handle_.id(), fragmentShader.id());
  gl.LinkProgram(handle_.id());
  // The shaders may go now: attached shaders live as long as the program needs them.
  GLint linked = GL_FALSE;
  gl.GetProgramiv(handle_.id(), GL_LINK_STATUS, &linked);
  if (!linked) {
    throw Error("program \"" + vertex.name + " + " + fragment.name + "\" failed to link:\n" +
                programLog(gl, handle_.id()));
  }
  checkError(gl, ("building program \"" + vertex.name + " + " + fragment.name + "\"").c_str());
}

void Program::use() const { handle_.gl().UseProgram(handle_.id()); }

GLint Program::location(const char* name) const {
  const auto cached = locations_.find(name);
  if (cached != locations_.end()) return cached->second;
  const GLint at = handle_.gl().GetUniformLocation(handle_.id(), name);
  locations_.emplace(name, at);
  return at;
}

void Program::set(const char* name, int value) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform1i(handle_.id(), at, value);
}

void Program::set(const char* name, float value) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform1f(handle_.id(), at, value);
}

void Program::set(const char* name, float x, float y) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform2f(handle_.id(), at, x, y);
}

void Program::set(const char* name, float x, float y, float z, float w) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform4f(handle_.id(), at, x, y, z, w);
}

void Program::setMatrix4(const char* name, const float* columnMajor16) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniformMatrix4fv(handle_.id(), at, 1, GL_FALSE, columnMajor16);
}

void Program::setArray(const char* name, const float* values, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform1fv(handle_.id(), at, count, values);
}

void Program::setIntArray(const char* name, const int* values, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform1iv(handle_.id(), at, count, values);
}

void Program::setVec2Array(const char* name, const float* xy, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform2fv(handle_.id(), at, count, xy);
}

void Program::setVec3Array(const char* name, const float* xyz, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform3fv(handle_.id(), at, count, xyz);
}

void Program::setMatrix3Array(const char* name, const float* columnMajor, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniformMatrix3fv(handle_.id(), at, count, GL_FALSE, columnMajor);
}

void Program::setVec4Array(const char* name, const float* xyzw, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniform4fv(handle_.id(), at, count, xyzw);
}

void Program::setMatrix4Array(const char* name, const float* columnMajor, int count) const {
  const GLint at = location(name);
  if (at >= 0) handle_.gl().ProgramUniformMatrix4fv(handle_.id(), at, count, GL_FALSE, columnMajor);
}

// --- AnySamplesQuery ---------------------------------------------------------------------

AnySamplesQuery::AnySamplesQuery(const Functions& gl) {
  GLuint id = 0;
  gl.GenQueries(1, &id);
  handle_ = Handle<QueryDeleter>(&gl, id);
  checkError(gl, "creating a query");
}

void AnySamplesQuery::begin() const { handle_.gl().BeginQuery(GL_ANY_SAMPLES_PASSED, handle_.id()); }

bool AnySamplesQuery::endAndRead() const {
  const Functions& gl = handle_.gl();
  gl.EndQuery(GL_ANY_SAMPLES_PASSED);
  GLuint passed = 0;
  gl.GetQueryObjectuiv(handle_.id(), GL_QUERY_RESULT, &passed);
  checkError(gl, "reading a query");
  return passed != 0;
}

// --- FullscreenTriangle ------------------------------------------------------------------

FullscreenTriangle::FullscreenTriangle(const Functions& gl) {
  GLuint id = 0;
  gl.GenVertexArrays(1, &id);
  vao_ = Handle<VertexArrayDeleter>(&gl, id);
  checkError(gl, "creating the full-screen triangle's vertex array");
}

void FullscreenTriangle::draw(const char* pass) const {
  const Functions& gl = vao_.gl();
  gl.BindVertexArray(vao_.id());
  if (!passProfileOn()) {
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    checkError(gl, pass);
    return;
  }
  gl.Finish();  // the work queued before this pass is not its time
  const auto start = std::chrono::steady_clock::now();
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  gl.Finish();
  const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  checkError(gl, pass);
  recordPassTime(pass, took.count());
}

}  // namespace taa::gl
