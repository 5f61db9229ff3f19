#pragma once
// The lecture's "At the Intersection" slide drawn on the model (--intersection with --probe): at the
// probed point the incoming ray I (along -V, from the eye), the normal N, the reflected ray R and the
// refracted ray T (Snell's law at this one surface; none past the critical angle), with theta_i,
// theta_t and the indices eta_i, eta_t, and the Fresnel split of the light arriving along I:
// R_par, R_perp, R = (R_par + R_perp) / 2 reflected and 1 - R transmitted (the exact formulas,
// whatever --fresnel the picture uses). CPU-drawn into a finished frame, like the formula overlay.
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace shadelab {

// Where the diagram stands: the probed point, its unit normal (as the pixel's mode has it there), and
// the pane it was probed in (image pixels, top-left origin) with that pane's clipFromWorld.
struct IntersectionPoint {
    glm::vec3 posWorld{0.0f};
    glm::vec3 nrmWorld{0.0f, 1.0f, 0.0f};
    glm::mat4 clipFromWorld{1.0f};
    float paneX = 0.0f, paneY = 0.0f, paneWidth = 1.0f, paneHeight = 1.0f;
};

// The diagram's numbers (the slide's): the angles in degrees, the indices and the Fresnel terms.
struct IntersectionNumbers {
    float thetaIDeg = 0.0f;
    float thetaTDeg = 0.0f;  // 0 past the critical angle
    bool totalInternal = false;
    float etaI = 1.0f, etaT = 1.5f;
    float rParallel = 0.0f, rPerpendicular = 0.0f, r = 0.0f;  // R_par, R_perp, their mean
};
IntersectionNumbers intersectionNumbers(const Scene& scene, const IntersectionPoint& at);

// Draws the arrows and their labels at the point and the numbers in a box beside them. Throws
// InputError when the DejaVu Sans font (fonts-dejavu-core) is missing.
void drawIntersectionDiagram(Image& image, const Scene& scene, const IntersectionPoint& at);

}  // namespace shadelab
