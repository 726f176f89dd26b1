/**
 * @class vtkUnstructuredVolumeFloatTarget
 * @brief The premultiplied RGBA32F image a mapper draws into, with a copy of the scene's depth.
 *
 * Every mapper integrates in float, away from VTK's 8-bit framebuffer, and blends the result into
 * the scene at the end: Resize (per frame; reallocates only on change), CopySceneDepth (the depth of
 * the opaque geometry VTK drew so far, so volumes end there; ClearSceneDepth where VTK drew none),
 * Bind / Unbind around the mapper's
 * passes, ReadBack (KeepFloatImage) and Composite (ONE, ONE_MINUS_SRC_ALPHA over the viewport).
 * Clear and Composite take the pixels the volume can cover this frame and touch only those: the
 * image holds nothing elsewhere, as each clear also takes back what the frame before drew.
 * A mapper that masks finished pixels may attach its own depth texture. (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeFloatTarget_h
#define vtkUnstructuredVolumeFloatTarget_h

#include "uvScreenRectangle.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

class vtkImageData;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkTextureObject;

class vtkUnstructuredVolumeFloatTarget
{
public:
  vtkUnstructuredVolumeFloatTarget();
  ~vtkUnstructuredVolumeFloatTarget();

  /// Allocates the colour image and the scene-depth copy at width x height (only when changed),
  /// for a tile of the window of tileWidth x tileHeight pixels. A tile larger than the image
  /// (ImageSampleDistance above 1): the scene's depth is copied at the tile's size and resampled to
  /// the image's, and Composite stretches the image over the tile (linear filtering).
  void Resize(vtkOpenGLRenderWindow* window, int width, int height, int tileWidth, int tileHeight);
  /// Attaches `depth` (a depth texture of the target's size) to the framebuffer, or detaches with null.
  void AttachDepth(vtkTextureObject* depth);

  /// Copies the depth of VTK's current framebuffer at (originX, originY) into SceneDepth. A
  /// multisampled framebuffer cannot be copied from: SceneDepth is then the far plane and false is
  /// returned. Call before Bind.
  bool CopySceneDepth(int originX, int originY);
  /// Sets SceneDepth to the far plane, for a frame in which nothing was drawn before the volumes:
  /// a clear instead of the copy, which CPU rasterisers convert pixel by pixel. Only where SceneDepth
  /// holds something else (a copy, or new storage). The target must be bound.
  void ClearSceneDepth();

  /// Saves VTK's framebuffer bindings, binds the target (one draw buffer) and sets the viewport.
  void Bind();
  /// Clears the colour image to transparent black where this frame may draw (`drawn`, image pixels)
  /// and where the last frame may have drawn (everything after an allocation), so that the whole
  /// image is transparent but for what this frame draws inside `drawn`. The target must be bound.
  void Clear(const uv::PixelRectangle& drawn);
  /// The colour image into `image` (made when null); the target must be bound.
  void ReadBack(vtkSmartPointer<vtkImageData>& image);
  /// Restores the bindings Bind saved.
  void Unbind();
  /// Blends the colour image over VTK's scene, over the tile at (originX, originY), only where the
  /// image's pixels `drawn` land (the rest is transparent); false when the composite shaders do not
  /// compile.
  bool Composite(int originX, int originY, const uv::PixelRectangle& drawn);

  /// The pixels this frame may draw, as the last Clear took them.
  const uv::PixelRectangle& GetDrawnPixels() const { return this->LastDrawn; }

  vtkTextureObject* GetColor();
  vtkTextureObject* GetSceneDepth();
  vtkOpenGLFramebufferObject* GetFramebuffer();
  /// An empty vertex array, for passes whose vertices come from gl_VertexID or buffer textures.
  vtkOpenGLVertexArrayObject* GetNoAttributes();

  void Release();

private:
  vtkUnstructuredVolumeFloatTarget(const vtkUnstructuredVolumeFloatTarget&) = delete;
  void operator=(const vtkUnstructuredVolumeFloatTarget&) = delete;

  bool Reduced() const { return this->TileWidth != this->Width || this->TileHeight != this->Height; }

  vtkNew<vtkTextureObject> Color, SceneDepth;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  // A reduced image's scene depth at the tile's size, read from by the resampling blit.
  vtkNew<vtkTextureObject> TileDepth;
  vtkNew<vtkOpenGLFramebufferObject> TileFramebuffer;
  vtkNew<vtkOpenGLVertexArrayObject> NoAttributes;
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkTextureObject* AttachedDepth = nullptr;
  bool SceneDepthIsFar = false; // SceneDepth holds the far plane everywhere (ClearSceneDepth)
  bool ColorIsNew = true;        // Color was allocated since the last Clear: it holds anything
  uv::PixelRectangle LastDrawn{ 0, 0, 0, 0 }; // the pixels the last Clear left to be drawn
  int Width = 0, Height = 0, TileWidth = 0, TileHeight = 0;
};

#endif
