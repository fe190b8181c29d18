#include "trace/render.h"

namespace povwall::trace {

Image render_scene(const Scene& scene, const RenderSettings& settings, RenderStats* stats) {
    Image image(settings.width, settings.height);
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i + 0] = scene.background.rgb.r;
        image.rgba[i + 1] = scene.background.rgb.g;
        image.rgba[i + 2] = scene.background.rgb.b;
        image.rgba[i + 3] = 1.0f;
    }
    return image;
}

}  // namespace povwall::trace
