#pragma once
// "The view changed", from one place: every input the 3D view's image is drawn from,
// as revision counters and sizes, in ViewInputs; ViewRevision turns them into one counter that moves
// when any of them does. Whatever must restart when the view changes (a progressive sum) keeps that
// one number, not its own list of inputs. GL-free.
#include <cstdint>
#include <optional>
#include <tuple>

namespace shadelab {

struct ViewInputs {
    std::uint64_t scene = 0;      // SceneDocument::revision(): every edit, the camera's (orbit, zoom, framing) too
    std::uint64_t geometry = 0;   // SceneDocument::geometryRevision(): the meshes were rebuilt
    std::uint64_t renderer = 0;   // the renderer's generation: F5 built new programs
    std::uint64_t animation = 0;  // AnimationPlayback::step(): the frames a playing animation moved the scene
    std::uint64_t width = 0, height = 0;  // the render target's pixels (a resize, a reduced moving frame)
    std::uint64_t moving = 0;             // 1: a moving frame (ViewQuality), drawn with fewer shadow samples

    auto tied() const { return std::tie(scene, geometry, renderer, animation, width, height, moving); }
};
// A new input is a new field: it must go into tied() too, or changing it would not change the view.
static_assert(sizeof(ViewInputs) == 7 * sizeof(std::uint64_t), "a ViewInputs field missing from tied()?");

class ViewRevision {
public:
    // The revision of a view drawn from `inputs`: the last call's while they are the same, one more as
    // soon as any of them differs.
    std::uint64_t of(const ViewInputs& inputs) {
        if (!last_ || last_->tied() != inputs.tied()) {
            last_ = inputs;
            ++revision_;
        }
        return revision_;
    }

private:
    std::optional<ViewInputs> last_;
    std::uint64_t revision_ = 0;
};

}  // namespace shadelab
