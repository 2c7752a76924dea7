// The OpenGL 3.3 core entry points the renderer uses, loaded through a
// GLContext (private to render/). Call them as gl.Clear(...).
#pragma once

#include "rotinterp/render/context.h"

#include <GL/glcorearb.h>

namespace rotinterp::render::detail {

#define ROTINTERP_GL_FUNCTIONS(X)                                              \
  X(PFNGLGETSTRINGPROC, GetString)                                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                         \
  X(PFNGLGETERRORPROC, GetError)                                               \
  X(PFNGLVIEWPORTPROC, Viewport)                                               \
  X(PFNGLSCISSORPROC, Scissor)                                                 \
  X(PFNGLENABLEPROC, Enable)                                                   \
  X(PFNGLDISABLEPROC, Disable)                                                 \
  X(PFNGLCLEARPROC, Clear)                                                     \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                           \
  X(PFNGLCLEARDEPTHPROC, ClearDepth)                                           \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                             \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                             \
  X(PFNGLCOLORMASKPROC, ColorMask)                                             \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                             \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                           \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                         \
  X(PFNGLFINISHPROC, Finish)                                                   \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                           \
  X(PFNGLDRAWELEMENTSINSTANCEDPROC, DrawElementsInstanced)                     \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                 \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                           \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                           \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                           \
  X(PFNGLBUFFERDATAPROC, BufferData)                                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                     \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                 \
  X(PFNGLVERTEXATTRIBDIVISORPROC, VertexAttribDivisor)                         \
  X(PFNGLCREATESHADERPROC, CreateShader)                                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                               \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                             \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                           \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                     \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                           \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                             \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                             \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                                             \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                                             \
  X(PFNGLUNIFORM4FPROC, Uniform4f)                                             \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                               \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                 \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                 \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                           \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                               \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                               \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample)   \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                         \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                 \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                         \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                         \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                           \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                     \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                   \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)

struct GLApi {
#define ROTINTERP_GL_DECLARE(type, name) type name = nullptr;
  ROTINTERP_GL_FUNCTIONS(ROTINTERP_GL_DECLARE)
#undef ROTINTERP_GL_DECLARE

  // Loads every entry point; the error names the first one missing.
  Status load(const GLContext& context);
};

}  // namespace rotinterp::render::detail
