// The automatic image sample distance of interactive frames (AutoAdjustSampleDistances): the
// distance between rays, in pixels, that lets a frame fit the time the renderer allows it. VTK-free;
// the mapper base records what each frame took and asks for the next frame's distance.
#ifndef uvAdaptiveImageSampleDistance_h
#define uvAdaptiveImageSampleDistance_h

#include <algorithm>
#include <cmath>

namespace uv
{

/// Frames allowed this long or longer are still frames: drawn at the user's own distance. VTK's
/// interactor allows a fraction of a second while the camera moves and thousands of seconds at rest.
constexpr double StillFrameSeconds = 1.0;

class AdaptiveImageSampleDistance
{
public:
  struct Limits
  {
    double Still = 1.0;   ///< the user's distance: still frames, and the finest interactive one
    double Minimum = 1.0; ///< no interactive frame finer than this
    double Maximum = 8.0; ///< nor coarser than this (unless Still or Minimum is)
  };

  /// Whether a frame allowed `allowedSeconds` is interactive (NaN and infinity are not).
  static bool IsInteractive(double allowedSeconds)
  {
    return allowedSeconds > 0.0 && allowedSeconds < StillFrameSeconds;
  }

  /// The next frame's distance. Still frames: Limits::Still. Interactive ones: the last recorded
  /// frame's distance scaled so that the pixels drawn, which cost most of a reduced frame, scale with
  /// the time allowed over the time taken (the image's pixels go as 1 / distance^2); kept where the
  /// last interactive frame took within Tolerance of the time allowed, so that noise does not make
  /// the image flicker between sizes; and changed by at most MaximumStep times either way, so that
  /// one frame slowed by one-off work (a first ray walk building its adjacency, a resized image)
  /// costs a frame or two of a coarser image, not the coarsest. With no frame recorded yet, the
  /// finest allowed.
  double Next(double allowedSeconds, const Limits& limits) const
  {
    if (!IsInteractive(allowedSeconds))
      return limits.Still;
    const double finest = std::max(limits.Still, limits.Minimum);
    const double coarsest = std::max(finest, limits.Maximum);
    if (!(this->LastSeconds > 0.0) || !(this->LastDistance >= 1.0))
      return finest;
    const double ratio = this->LastSeconds / allowedSeconds;
    double distance = this->LastDistance * std::sqrt(ratio);
    if (this->LastInteractive && std::abs(ratio - 1.0) <= Tolerance)
      distance = this->LastDistance;
    distance = std::min(MaximumStep * this->LastDistance, std::max(this->LastDistance / MaximumStep, distance));
    return std::min(coarsest, std::max(finest, distance));
  }

  /// Records a frame drawn at `distance` in `seconds`, allowed `allowedSeconds`. Frames that did
  /// one-off work (building a mesh) should not be recorded: they say nothing of the next frame.
  void Record(double distance, double seconds, double allowedSeconds)
  {
    this->LastDistance = distance;
    this->LastSeconds = seconds;
    this->LastInteractive = IsInteractive(allowedSeconds);
  }

  /// The relative difference between the time taken and allowed that keeps the distance.
  static constexpr double Tolerance = 0.15;
  /// The most a distance changes from one frame to the next, as a factor.
  static constexpr double MaximumStep = 2.0;

private:
  double LastDistance = 0.0, LastSeconds = 0.0;
  bool LastInteractive = false;
};

} // namespace uv

#endif
