// Move-only RAII wrappers for the GL objects taa uses. Each holds the Functions table of the
// context that made it and must be destroyed while that context is current (and before it).
#pragma once

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gl/gl_functions.h"

namespace taa::gl {

// Shared move-only handle logic: owns one GL name and deletes it with the given deleter.
template <typename Deleter>
class Handle {
 public:
  Handle() = default;
  Handle(const Functions* gl, GLuint id) : gl_(gl), id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : gl_(other.gl_), id_(std::exchange(other.id_, 0)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      gl_ = other.gl_;
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  GLuint id() const { return id_; }
  const Functions& gl() const { return *gl_; }
  explicit operator bool() const { return id_ != 0; }

 private:
  void reset() {
    if (id_ != 0) Deleter{}(*gl_, id_);
    id_ = 0;
  }
  const Functions* gl_ = nullptr;
  GLuint id_ = 0;
};

struct TextureDeleter {
  void operator()(const Functions& gl, GLuint id) const { gl.DeleteTextures(1, &id); }
};
struct FramebufferDeleter {
  void operator()(const Functions& gl, GLuint id) const { gl.DeleteFramebuffers(1, &id); }
};
struct ProgramDeleter {
  void operator()(const Functions& gl, GLuint id) const { gl.DeleteProgram(id); }
};
struct QueryDeleter {
  void operator()(const Functions& gl, GLuint id) const { gl.DeleteQueries(1, &id); }
};
struct VertexArrayDeleter {
  void operator()(const Functions& gl, GLuint id) const { gl.DeleteVertexArrays(1, &id); }
};

// A 2D texture with nearest or linear filtering and clamp-to-edge wrapping.
// Pixel rows are uploaded in memory order: row 0 is texel row 0 (raster j = 0, the top row
// in taa's convention), so gl_FragCoord.y and texture v both count raster rows from the top.
class Texture {
 public:
  enum class Filter { Nearest, Linear };

  Texture() = default;
  // internalFormat e.g. GL_RGBA32F, GL_R32F, GL_RG32F, GL_RGBA16F.
  Texture(const Functions& gl, int width, int height, GLenum internalFormat,
          Filter filter = Filter::Nearest);

  // Uploads width*height pixels of `components` samples each (1, 2, 3 or 4), tightly packed;
  // `type` GL_FLOAT or GL_HALF_FLOAT. Half data into a 16F texture is a plain copy.
  void upload(const void* pixels, int components, GLenum type);
  void upload(const float* pixels, int components) { upload(pixels, components, GL_FLOAT); }
  void bind(int unit) const;
  // Binds the texture to image unit `unit` for a shader's image stores (write only; the
  // context must have them: ContextInfo::fragmentImageUnits). A pass that stores into it
  // must be followed by MemoryBarrier before the texture is read.
  void bindImage(int unit) const;
  // Reads the texture back as RGBA of `type` (GL_FLOAT or GL_HALF_FLOAT), row 0 first.
  void readRGBA(void* pixels, GLenum type) const;

  GLuint id() const { return handle_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Handle<TextureDeleter> handle_;
  int width_ = 0, height_ = 0;
  GLenum format_ = 0;  // the internal format
};

// A 2D array texture (nearest filtering, clamp to edge): `layers` images of one size and
// format, rows uploaded like Texture's (row 0 = raster row 0). The window resolve keeps its
// ring of frames in these, one layer a frame, so one shader pass reads them all.
class TextureArray {
 public:
  TextureArray() = default;
  TextureArray(const Functions& gl, int width, int height, int layers, GLenum internalFormat);

  // Uploads one layer: width*height pixels of `components` samples of `type`, tightly packed.
  void upload(int layer, const void* pixels, int components, GLenum type);
  // Uploads rows firstRow..firstRow+rows-1 of one layer, tightly packed as upload's.
  void uploadRows(int layer, int firstRow, int rows, const void* pixels, int components,
                  GLenum type);
  void bind(int unit) const;

  GLuint id() const { return handle_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }

 private:
  Handle<TextureDeleter> handle_;
  int width_ = 0, height_ = 0, layers_ = 0;
};

// The most layers, up to `wanted`, of a `width` x `height` texture array of `internalFormat`
// the driver accepts (asked with a proxy texture: nothing is allocated); 0 if not even one.
// llvmpipe refuses a texture over about 1.6 GB: 48 layers of 1080p RGBA32UI, 12 of 4K.
int largestTextureArrayLayers(const Functions& gl, int width, int height, int wanted,
                              GLenum internalFormat);

// What a framebuffer draws into at one location: a texture, or one layer of a texture array.
// Converts implicitly from a Texture pointer (nullptr: nothing attached there).
struct Attachment {
  Attachment(const Texture* texture)  // NOLINT: implicit on purpose
      : id(texture ? texture->id() : 0),
        width(texture ? texture->width() : 0),
        height(texture ? texture->height() : 0),
        present(texture != nullptr) {}
  Attachment(const TextureArray& array, int arrayLayer)
      : id(array.id()), width(array.width()), height(array.height()), layer(arrayLayer),
        present(true) {}
  GLuint id = 0;
  int width = 0, height = 0;
  int layer = -1;  // >= 0: a layer of an array texture
  bool present = false;
};

// A framebuffer object with one or more colour attachments of one size; fragment output
// location i writes attachment i. Throws taa::Error if incomplete.
class Framebuffer {
 public:
  Framebuffer() = default;
  Framebuffer(const Functions& gl, const Texture& colorAttachment);
  // Attachment i receives the fragment shader's output at location i; an absent entry leaves
  // that location unattached (its output is dropped).
  Framebuffer(const Functions& gl, const std::vector<Attachment>& colorAttachments);

  // Binds for drawing and sets the viewport to the attachments' size.
  void bind() const;
  // Reads attachment `index` back as tightly packed RGBA floats, row 0 first.
  std::vector<float> readRGBA(int index = 0) const;
  // The same into `pixels` (width*height*4 samples of `type`, GL_FLOAT or GL_HALF_FLOAT). GL
  // rounds a float attachment to half to nearest even, as Imath does (tests/gl checks it), so
  // reading back as half gives the file what narrowing on the CPU would.
  void readRGBA(void* pixels, GLenum type, int index = 0) const;

  GLuint id() const { return handle_.id(); }

 private:
  Handle<FramebufferDeleter> handle_;
  int width_ = 0, height_ = 0;
  int attachments_ = 0;
};

// GLSL text ready to compile ("#version" on its first line), e.g. generated code.
struct ShaderSource {
  std::string name;                    // shown in error messages, e.g. "resolve.frag"
  std::string text;                    // the complete source
  std::vector<std::string> fileNames;  // `#line` source-string number -> file; empty: {name}
};

// An embedded file (glsl/) with its includes expanded and `defines` ("#define NAME VALUE")
// inserted right after its #version line. Throws taa::Error for an unknown name.
ShaderSource embeddedShaderSource(const std::string& name,
                                  const std::vector<std::string>& defines = {});

// A linked vertex + fragment program.
class Program {
 public:
  Program() = default;
  // vertexShader / fragmentShader are names of embedded files (e.g. "fullscreen.vert");
  // `defines` lines ("#define NAME VALUE") go right after the #version line.
  // A compile or link failure throws taa::Error with the driver's log and the shader name.
  Program(const Functions& gl, const std::string& vertexShader, const std::string& fragmentShader,
          const std::vector<std::string>& defines = {});
  // The same from source text; errors name the ShaderSource and map lines through fileNames.
  Program(const Functions& gl, const ShaderSource& vertex, const ShaderSource& fragment);

  void use() const;
  // Uniform setters (glProgramUniform*: the program need not be in use). A name the linker
  // removed (unused) is silently ignored, as GL does. Locations are looked up once per name
  // and cached, so setting uniforms by name every frame costs no GL queries.
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, float x, float y) const;
  void set(const char* name, float x, float y, float z, float w) const;
  void setMatrix4(const char* name, const float* columnMajor16) const;
  void setArray(const char* name, const float* values, int count) const;  // float name[count]
  void setIntArray(const char* name, const int* values, int count) const;  // int name[count]
  void setVec2Array(const char* name, const float* xy, int count) const;   // vec2 name[count]
  void setVec3Array(const char* name, const float* xyz, int count) const;   // vec3 name[count]
  void setVec4Array(const char* name, const float* xyzw, int count) const;  // vec4 name[count]
  void setMatrix3Array(const char* name, const float* columnMajor, int count) const;
  void setMatrix4Array(const char* name, const float* columnMajor, int count) const;

  GLuint id() const { return handle_.id(); }

 private:
  GLint location(const char* name) const;
  Handle<ProgramDeleter> handle_;
  mutable std::unordered_map<std::string, GLint> locations_;
};

// Draws one triangle covering the viewport; the vertex shader "fullscreen.vert" derives the
// positions from gl_VertexID, so no vertex buffer is needed (only the VAO core profile requires).
class FullscreenTriangle {
 public:
  FullscreenTriangle() = default;
  explicit FullscreenTriangle(const Functions& gl);
  // Draws, then checks for a GL error naming `pass` (and times it under TAA_GL_PROFILE).
  void draw(const char* pass) const;

 private:
  Handle<VertexArrayDeleter> vao_;
};

// An occlusion query: whether any fragment passed while it was active (GL_ANY_SAMPLES_PASSED).
class AnySamplesQuery {
 public:
  AnySamplesQuery() = default;
  explicit AnySamplesQuery(const Functions& gl);
  void begin() const;
  // Ends the query and waits for its answer.
  bool endAndRead() const;

 private:
  Handle<QueryDeleter> handle_;
};

// Throws taa::Error naming `what` if glGetError reports an error (checks cost little here:
// one per pass, not per pixel).
void checkError(const Functions& gl, const char* what);

}  // namespace taa::gl
