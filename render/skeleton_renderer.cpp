#include "render/skeleton_renderer.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "render/gl_context.h"
#include "render/ground_layer.h"
#include "render/overlay_layer.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace mgp::render {

namespace {

// ---- Shaders (GLSL 3.30 core, embedded so installs need no asset files) -------------------------

// Solids are drawn instanced, one draw per (mesh, pass). Per instance: iA = (start or centre,
// radius), iB = (end, end radius) for tubes, iColour = (sRGB, alpha), iExtra.x = emissive.
const char* kLitVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec4 iA;
layout(location = 3) in vec4 iB;
layout(location = 4) in vec4 iColour;
layout(location = 5) in vec4 iExtra;
uniform mat4 uViewProj;
uniform int uTube;       // 0: sphere at iA.xyz with radius iA.w, 1: tapered tube iA -> iB
out vec3 vWorld;
out vec3 vNormal;
flat out vec4 vColour;
flat out float vEmissive;
void main() {
    vec3 p;
    vec3 n;
    if (uTube == 1) {
        vec3 axis = iB.xyz - iA.xyz;
        float len = max(length(axis), 1e-6);
        vec3 ay = axis / len;
        vec3 helper = abs(ay.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 ax = normalize(cross(helper, ay));
        vec3 az = cross(ax, ay);
        float t = aPosition.y;
        vec3 radial = aPosition.x * ax + aPosition.z * az;
        p = iA.xyz + ay * (len * t) + radial * mix(iA.w, iB.w, t);
        n = normalize(radial * len + ay * (iA.w - iB.w));
    } else {
        p = iA.xyz + aPosition * iA.w;
        n = aNormal;
    }
    vWorld = p;
    vNormal = n;
    vColour = vec4(pow(iColour.rgb, vec3(2.2)), iColour.a);
    vEmissive = iExtra.x;
    gl_Position = uViewProj * vec4(p, 1.0);
}
)";

const char* kLitFs = R"(#version 330 core
in vec3 vWorld;
in vec3 vNormal;
flat in vec4 vColour;     // linear rgb, alpha
flat in float vEmissive;
out vec4 fragColour;
uniform vec3 uEye;
uniform vec3 uKeyDir;     // towards the key light (world)
uniform vec3 uFillDir;    // towards the fill light (world)
void main() {
    vec3 n = normalize(vNormal);
    vec3 v = normalize(uEye - vWorld);
    if (dot(n, v) < 0.0) n = -n;
    vec3 base = vColour.rgb;
    float hemi = 0.5 + 0.5 * n.y;
    vec3 ambient = mix(vec3(0.10, 0.095, 0.09), vec3(0.30, 0.32, 0.36), hemi);
    float key = max(dot(n, uKeyDir), 0.0);
    float fill = max(dot(n, uFillDir), 0.0);
    vec3 h = normalize(uKeyDir + v);
    float spec = pow(max(dot(n, h), 0.0), 48.0) * 0.22 * step(0.0, key);
    float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0) * 0.30;
    vec3 lin = base * (ambient + key * vec3(1.0, 0.96, 0.90) * 1.05 + fill * vec3(0.55, 0.62, 0.75) * 0.35)
             + vec3(spec) + rim * vec3(0.55, 0.62, 0.75) * (0.4 + 0.6 * hemi) + base * vEmissive;
    lin = lin / (1.0 + 0.15 * lin);  // gentle shoulder so highlights do not clip
    fragColour = vec4(pow(lin, vec3(1.0 / 2.2)), vColour.a);
}
)";

const char* kGroundVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProj;
uniform vec3 uCentre;    // grid centre (x, ground height, z)
uniform float uHalfSize;
out vec3 vWorld;
void main() {
    vWorld = vec3(uCentre.x + aPosition.x * uHalfSize, uCentre.y, uCentre.z + aPosition.z * uHalfSize);
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
)";

const char* kGroundFs = R"(#version 330 core
in vec3 vWorld;
out vec4 fragColour;
uniform vec3 uGround;
uniform vec3 uMinor;
uniform vec3 uMajor;
uniform vec3 uFocus;        // where the character stands (fade and shadow centre)
uniform float uFadeRadius;
uniform vec3 uTop;          // background gradient, to fade into (the ground is opaque)
uniform vec3 uHorizon;
uniform float uViewportHeight;
uniform sampler2D uShadow;  // contact-shadow factor (1 = lit), baked on the CPU
uniform vec4 uShadowRect;   // x, z of its corner, 1 / its size in x and z (cm)
float gridLine(vec2 p, float spacing, float widthPx) {
    vec2 c = p / spacing;
    vec2 d = max(fwidth(c), vec2(1e-6));
    vec2 g = abs(fract(c - 0.5) - 0.5) / d;
    float line = 1.0 - clamp(min(g.x, g.y) / widthPx, 0.0, 1.0);
    // Fade a grid level out before its lines merge into moire.
    float density = max(d.x, d.y);
    return line * (1.0 - smoothstep(0.12, 0.35, density));
}
void main() {
    vec2 p = vWorld.xz;
    vec3 c = uGround;
    c = mix(c, uMinor, gridLine(p, 10.0, 1.0) * 0.8);
    c = mix(c, uMajor, gridLine(p, 100.0, 1.4));
    // World axes through the origin: X reddish, Z bluish.
    vec2 w = fwidth(p);
    float ax = 1.0 - clamp(abs(p.y) / (1.6 * w.y), 0.0, 1.0);
    float az = 1.0 - clamp(abs(p.x) / (1.6 * w.x), 0.0, 1.0);
    c = mix(c, vec3(0.70, 0.30, 0.28), ax * 0.8);
    c = mix(c, vec3(0.28, 0.42, 0.72), az * 0.8);
    vec2 uv = (p - uShadowRect.xy) * uShadowRect.zw;
    float shade = 1.0;
    if (all(greaterThan(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)))) shade = texture(uShadow, uv).r;
    c *= shade;
    float dist = length(p - uFocus.xz);
    float alpha = 1.0 - smoothstep(0.45 * uFadeRadius, uFadeRadius, dist);
    vec3 background = mix(uHorizon, uTop, smoothstep(0.0, 1.0, gl_FragCoord.y / uViewportHeight));
    fragColour = vec4(mix(background, c, alpha), 1.0);
}
)";

const char* kBackgroundVs = R"(#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    gl_Position = vec4(p, 1.0, 1.0);  // on the far plane: only pixels nothing has covered
}
)";

const char* kBackgroundFs = R"(#version 330 core
out vec4 fragColour;
uniform vec3 uTop;
uniform vec3 uHorizon;
uniform float uViewportHeight;
void main() {
    fragColour = vec4(mix(uHorizon, uTop, smoothstep(0.0, 1.0, gl_FragCoord.y / uViewportHeight)), 1.0);
}
)";

const char* kTextVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform vec2 uViewport;
uniform vec2 uOffset;
uniform float uScale;
void main() {
    vec2 px = aPosition.xy * uScale + uOffset;
    gl_Position = vec4(px.x / uViewport.x * 2.0 - 1.0, 1.0 - px.y / uViewport.y * 2.0, 0.0, 1.0);
}
)";

const char* kTextFs = R"(#version 330 core
out vec4 fragColour;
uniform vec4 uColour;
void main() { fragColour = uColour; }
)";

constexpr int kMaxBlobs = 64;
constexpr int kShadowRes = 128;

// Where the frame is seen from: the camera's matrices and the lights that follow it.
struct FrameView {
    glm::mat4 viewProj;
    glm::vec3 eye, keyDir, fillDir;
};

}  // namespace

struct SceneRenderer::Impl {
    ShaderProgram lit, ground, background, text;
    GpuMesh sphere, smallSphere, tinySphere, tube, thinTube, quad;
    unsigned instanceVbo = 0;
    unsigned shadowTexture = 0;
    std::vector<std::uint8_t> shadowTexels;
    std::vector<float> shadowShade;  // the texels' shade before rounding

    // Bakes the contact shadows (a product of gaussian blobs) into a kShadowRes² texture over
    // the square that holds them; returns (corner x, corner z, 1/size, 1/size) for the shader.
    glm::vec4 updateShadowTexture(const Scene& scene);
    unsigned emptyVao = 0;
    unsigned textVao = 0, textVbo = 0;
    int samples = 4;
    std::unique_ptr<OverlayLayer> stillOverlays;   // without MSAA only (see Path::stillOverlay)
    std::unique_ptr<GroundLayer> backdrop;         // without MSAA, when the caller asks (useBackdropLayer)
    std::vector<unsigned char> backdropCandidate;  // the last view the backdrop did not hold
    unsigned fbo = 0, colourRb = 0, depthRb = 0;
    int fboWidth = 0, fboHeight = 0;

    void ensureFramebuffer(int w, int h) {
        if (fbo && w == fboWidth && h == fboHeight) return;
        releaseFramebuffer();
        glGenFramebuffers(1, &fbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glGenRenderbuffers(1, &colourRb);
        glBindRenderbuffer(GL_RENDERBUFFER, colourRb);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colourRb);
        glGenRenderbuffers(1, &depthRb);
        glBindRenderbuffer(GL_RENDERBUFFER, depthRb);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthRb);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw RenderError("renderer: the " + std::to_string(samples) + "x multisampled framebuffer of " +
                              std::to_string(w) + "x" + std::to_string(h) + " is incomplete");
        fboWidth = w;
        fboHeight = h;
    }
    // The phases of SceneRenderer::draw that use the renderer's GL objects.
    void beginFrame(const RenderStyle& s, int width, int height, unsigned targetFramebuffer);
    // Whether the frame could start from the backdrop (it then has): false for a view seen once.
    bool beginFrameFromBackdrop(const Scene& scene, const RenderStyle& s, const FrameView& view, int width, int height,
                                unsigned targetFramebuffer);
    void setFrameState(int width, int height);
    void useLit(const FrameView& view);
    // The ground quad; shadowRect as updateShadowTexture returns it (all 0: no shadows).
    void drawGround(const Scene& scene, const RenderStyle& s, const glm::mat4& viewProj, float viewportHeight,
                    const glm::vec4& shadowRect);
    void drawBackground(const RenderStyle& s, float viewportHeight);
    void drawCaption(const std::string& caption, int width, int height);
    void resolveFrame(int width, int height, unsigned targetFramebuffer);
    void drawStillOverlays(const Scene& scene, const RenderStyle& s, const FrameView& view, int width, int height,
                           unsigned targetFramebuffer);
    void releaseFramebuffer() {
        if (depthRb) glDeleteRenderbuffers(1, &depthRb);
        if (colourRb) glDeleteRenderbuffers(1, &colourRb);
        if (fbo) glDeleteFramebuffers(1, &fbo);
        fbo = colourRb = depthRb = 0;
    }
};

SceneRenderer::SceneRenderer(int msaaSamples) : impl_(std::make_unique<Impl>()) {
    Impl& r = *impl_;
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    r.samples = std::clamp(msaaSamples, 1, std::max(1, static_cast<int>(maxSamples)));
    if (r.samples > 1 && msaaSamples != r.samples)
        throw RenderError("renderer: " + std::to_string(msaaSamples) + "x MSAA requested, the driver offers at most " +
                          std::to_string(maxSamples) + "x");
    r.lit = ShaderProgram("lit", kLitVs, kLitFs);
    r.ground = ShaderProgram("ground", kGroundVs, kGroundFs);
    r.background = ShaderProgram("background", kBackgroundVs, kBackgroundFs);
    r.text = ShaderProgram("text", kTextVs, kTextFs);
    // llvmpipe's cost is mostly per triangle: small and thin things get coarser meshes.
    r.sphere = GpuMesh(makeSphere(20, 12));
    r.smallSphere = GpuMesh(makeSphere(10, 6));
    r.tinySphere = GpuMesh(makeSphere(6, 4));  // trail ticks: hundreds, a centimetre across
    r.tube = GpuMesh(makeTube(20));
    r.thinTube = GpuMesh(makeTube(8));
    r.quad = GpuMesh(makeQuadXZ());
    if (r.samples == 1) r.stillOverlays = std::make_unique<OverlayLayer>();
    glGenBuffers(1, &r.instanceVbo);
    glGenTextures(1, &r.shadowTexture);
    glBindTexture(GL_TEXTURE_2D, r.shadowTexture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kShadowRes, kShadowRes, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
    for (const GpuMesh* m : {&r.sphere, &r.smallSphere, &r.tinySphere, &r.tube, &r.thinTube})
        m->attachInstanceBuffer(r.instanceVbo, 2, 4);
    glGenVertexArrays(1, &r.emptyVao);
    glGenVertexArrays(1, &r.textVao);
    glGenBuffers(1, &r.textVbo);
    glBindVertexArray(r.textVao);
    glBindBuffer(GL_ARRAY_BUFFER, r.textVbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    glBindVertexArray(0);
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw RenderError("renderer setup: GL error " + std::to_string(err));
}

int SceneRenderer::msaaSamples() const { return impl_->samples; }

long SceneRenderer::overlayLayerDraws() const { return impl_->stillOverlays ? impl_->stillOverlays->draws() : 0; }

void SceneRenderer::useBackdropLayer(bool on) {
    if (!on || impl_->samples > 1)
        impl_->backdrop.reset();
    else if (!impl_->backdrop)
        impl_->backdrop = std::make_unique<GroundLayer>();
}

long SceneRenderer::backdropLayerDraws() const { return impl_->backdrop ? impl_->backdrop->draws() : 0; }

SceneRenderer::~SceneRenderer() {
    Impl& r = *impl_;
    r.releaseFramebuffer();
    glDeleteBuffers(1, &r.textVbo);
    glDeleteBuffers(1, &r.instanceVbo);
    glDeleteTextures(1, &r.shadowTexture);
    glDeleteVertexArrays(1, &r.textVao);
    glDeleteVertexArrays(1, &r.emptyVao);
}

namespace {

glm::vec3 sideColour(const RenderStyle& s, BodySide side) {
    switch (side) {
        case BodySide::kLeft: return s.leftBone;
        case BodySide::kRight: return s.rightBone;
        case BodySide::kCentre: break;
    }
    return s.centreBone;
}

// Collects solids with their colours, then draws them in two instanced calls (tubes, spheres).
struct Instance {
    glm::vec4 a, b, colour, extra;
};

struct Drawer {
    ShaderProgram& lit;
    const GpuMesh& sphere;
    const GpuMesh& smallSphere;
    const GpuMesh& tinySphere;
    const GpuMesh& tube;
    const GpuMesh& thinTube;
    unsigned instanceVbo;
    std::vector<Instance> tubes, thinTubes, balls, smallBalls, tinyBalls;
    glm::vec4 current{1.0f};
    float emissive = 0.0f;

    // The five batches, tubes first (the two tube batches are the first two).
    std::array<const std::vector<Instance>*, 5> batches() const {
        return {&tubes, &thinTubes, &balls, &smallBalls, &tinyBalls};
    }
    bool empty() const {
        for (const std::vector<Instance>* b : batches())
            if (!b->empty()) return false;
        return true;
    }
    void colour(const glm::vec3& c, float alpha = 1.0f, float emit = 0.0f) {
        current = glm::vec4(c, alpha);
        emissive = emit;
    }
    void ball(const glm::vec3& centre, float radius) {
        (radius < 2.7f ? smallBalls : balls)
            .push_back({glm::vec4(centre, radius), glm::vec4(0.0f), current, glm::vec4(emissive, 0, 0, 0)});
    }
    void tinyBall(const glm::vec3& centre, float radius) {
        tinyBalls.push_back({glm::vec4(centre, radius), glm::vec4(0.0f), current, glm::vec4(emissive, 0, 0, 0)});
    }
    void segment(const glm::vec3& a, const glm::vec3& b, float r0, float r1) {
        if (glm::length(b - a) < 1e-4f) return;
        (std::max(r0, r1) < 1.5f ? thinTubes : tubes)
            .push_back({glm::vec4(a, r0), glm::vec4(b, r1), current, glm::vec4(emissive, 0, 0, 0)});
    }
    void figure(const Figure& f, const RenderStyle& s, bool ghost) {
        for (const BoneSegment& b : f.bones) {
            if (!ghost) colour(tintedColour(sideColour(s, b.side), f));
            segment(b.startCm, b.endCm, b.startRadiusCm, b.endRadiusCm);
        }
        for (const JointBall& j : f.joints) {
            if (!ghost) colour(tintedColour(sideColour(s, j.side), f) * 0.92f);
            ball(j.centreCm, j.radiusCm);
        }
    }
    void drawBatch(const std::vector<Instance>& v, const GpuMesh& mesh, int isTube) {
        if (v.empty()) return;
        // Spheres are closed: cull their back faces (half the triangles). Tubes are open at the
        // ends, so both of their sides are drawn.
        if (isTube)
            glDisable(GL_CULL_FACE);
        else
            glEnable(GL_CULL_FACE);
        glBindBuffer(GL_ARRAY_BUFFER, instanceVbo);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Instance)), v.data(), GL_STREAM_DRAW);
        lit.set("uTube", isTube);
        mesh.drawInstanced(static_cast<int>(v.size()));
    }
    // Draws what was collected (tubes first), optionally keeping it for another pass.
    void flush(bool keep = false) {
        drawBatch(tubes, tube, 1);
        drawBatch(thinTubes, thinTube, 1);
        drawBatch(balls, sphere, 0);
        drawBatch(smallBalls, smallSphere, 0);
        drawBatch(tinyBalls, tinySphere, 0);
        glDisable(GL_CULL_FACE);
        if (!keep) {
            tubes.clear();
            thinTubes.clear();
            balls.clear();
            smallBalls.clear();
            tinyBalls.clear();
        }
    }
};

// Soft contact shadows: one gaussian blob under each joint of every shadow-casting figure,
// wider and fainter with height, plus a broad one under the figure.
int shadowBlobs(const Scene& scene, glm::vec4* blobs) {
    int n = 0;
    for (const Figure& f : scene.figures) {
        if (!f.castsShadow || f.ghost || f.joints.empty()) continue;
        glm::vec3 mean(0.0f);
        for (const JointBall& j : f.joints) mean += j.centreCm;
        mean /= static_cast<float>(f.joints.size());
        if (n < kMaxBlobs) blobs[n++] = glm::vec4(mean.x, mean.z, 38.0f, 0.22f);
        for (const JointBall& j : f.joints) {
            if (n >= kMaxBlobs) break;
            const float h = std::max(0.0f, j.centreCm.y - scene.groundHeightCm);
            const float strength = 0.42f * std::exp(-h / 45.0f);
            if (strength < 0.06f) continue;  // high joints add little and cost a lot per pixel
            blobs[n++] = glm::vec4(j.centreCm.x, j.centreCm.z, j.radiusCm * 1.6f + 0.30f * h, strength);
        }
    }
    return n;
}

}  // namespace

glm::vec4 SceneRenderer::Impl::updateShadowTexture(const Scene& scene) {
    glm::vec4 blobs[kMaxBlobs];
    const int n = shadowBlobs(scene, blobs);
    if (n == 0) return glm::vec4(0.0f, 0.0f, 0.0f, 0.0f);  // uv stays 0: no shadow anywhere
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int i = 0; i < n; ++i) {
        const glm::vec2 c(blobs[i].x, blobs[i].y);
        lo = glm::min(lo, c - glm::vec2(3.0f * blobs[i].z));
        hi = glm::max(hi, c + glm::vec2(3.0f * blobs[i].z));
    }
    const float size = std::max(hi.x - lo.x, hi.y - lo.y);
    const glm::vec2 corner = 0.5f * (lo + hi) - glm::vec2(0.5f * size);
    // Each blob reaches 3 of its widths (q < 9): it multiplies only the texels of its square, in
    // blob order, so every texel gets the products it would get from a loop over all blobs.
    const float step = size / static_cast<float>(kShadowRes);
    shadowShade.assign(static_cast<std::size_t>(kShadowRes) * kShadowRes, 1.0f);
    const auto texelIndex = [&](float cm, float origin) {
        return std::clamp(static_cast<int>(std::floor((cm - origin) / step - 0.5f)), 0, kShadowRes - 1);
    };
    for (int i = 0; i < n; ++i) {
        const glm::vec2 c(blobs[i].x, blobs[i].y);
        const float reach = 3.0f * blobs[i].z;
        // One texel of slack each way: the exact test below decides.
        const int x0 = std::max(0, texelIndex(c.x - reach, corner.x) - 1);
        const int x1 = std::min(kShadowRes - 1, texelIndex(c.x + reach, corner.x) + 1);
        const int y0 = std::max(0, texelIndex(c.y - reach, corner.y) - 1);
        const int y1 = std::min(kShadowRes - 1, texelIndex(c.y + reach, corner.y) + 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p = corner + (glm::vec2(static_cast<float>(x), static_cast<float>(y)) + 0.5f) * step;
                const glm::vec2 d = p - c;
                const float q = glm::dot(d, d) / (blobs[i].z * blobs[i].z);
                if (q < 9.0f)
                    shadowShade[static_cast<std::size_t>(y) * kShadowRes + x] *= 1.0f - blobs[i].w * std::exp(-q);
            }
    }
    shadowTexels.resize(shadowShade.size());
    for (int y = 0; y < kShadowRes; ++y)
        for (int x = 0; x < kShadowRes; ++x) {
            const std::size_t t = static_cast<std::size_t>(y) * kShadowRes + x;
            // Texels on the border stay fully lit so the clamp-to-edge lookup outside is 1.
            const bool border = x == 0 || y == 0 || x == kShadowRes - 1 || y == kShadowRes - 1;
            shadowTexels[t] =
                border ? 255 : static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(shadowShade[t], 0.0f, 1.0f)));
        }
    glBindTexture(GL_TEXTURE_2D, shadowTexture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kShadowRes, kShadowRes, GL_RED, GL_UNSIGNED_BYTE, shadowTexels.data());
    return glm::vec4(corner, 1.0f / size, 1.0f / size);
}

namespace {

// ---- The phases of SceneRenderer::draw ---------------------------------------------------------

FrameView frameViewOf(const OrbitCamera& camera, int width, int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 viewProj = camera.viewProjection(aspect);
    const glm::vec3 eye = camera.eye();
    const glm::mat4 view = camera.view();
    const glm::vec3 camRight(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 camUp(view[0][1], view[1][1], view[2][1]);
    const glm::vec3 camBack(view[0][2], view[1][2], view[2][2]);  // towards the eye
    // Lights follow the camera (a studio setup): key from the upper left, fill from the right.
    const glm::vec3 keyDir = glm::normalize(-0.55f * camRight + 0.85f * camUp + 0.65f * camBack);
    const glm::vec3 fillDir = glm::normalize(0.8f * camRight - 0.1f * camUp + 0.5f * camBack);
    return {viewProj, eye, keyDir, fillDir};
}

void addScenePath(Drawer& d, const Path& p, const RenderStyle& s) {
    d.colour(p.colour);
    for (std::size_t i = 1; i < p.pointsCm.size(); ++i)
        // Where two ticks overlap they already draw the line (llvmpipe pays per instance).
        if (p.tickRadiusCm <= 0.0f || glm::length(p.pointsCm[i] - p.pointsCm[i - 1]) > 1.5f * p.tickRadiusCm)
            d.segment(p.pointsCm[i - 1], p.pointsCm[i], p.radiusCm, p.radiusCm);
    // Balls round the joins of a thick path; a ticked path's ticks cover them.
    if (p.tickRadiusCm <= 0.0f)
        for (std::size_t i = 1; i + 1 < p.pointsCm.size(); ++i) d.ball(p.pointsCm[i], p.radiusCm);
    if (p.tickRadiusCm > 0.0f) {
        d.colour(glm::mix(p.colour, glm::vec3(1.0f), 0.35f));
        for (const glm::vec3& q : p.pointsCm) d.tinyBall(q, p.tickRadiusCm);
    }
    for (std::size_t k = 0; k < p.keysCm.size(); ++k) {
        const int i = static_cast<int>(k);
        if (i == p.selectedKey)
            d.colour(s.handleSelected, 1.0f, 0.45f);
        else if (i == p.hoveredKey)
            d.colour(s.handleHover, 1.0f, 0.45f);
        else
            d.colour(glm::mix(p.colour, glm::vec3(1.0f), 0.55f));
        d.ball(p.keysCm[k], p.keyRadiusCm() * (i == p.hoveredKey || i == p.selectedKey ? 1.3f : 1.0f));
    }
    if (p.currentPoint >= 0 && p.currentPoint < static_cast<int>(p.pointsCm.size())) {
        d.colour(glm::vec3(1.0f, 0.95f, 0.6f), 1.0f, 0.35f);
        d.ball(p.pointsCm[static_cast<std::size_t>(p.currentPoint)], p.radiusCm * 2.4f);
    }
}

void addTargetMarker(Drawer& d, const Target& t, const RenderStyle& s) {
    const glm::vec3 c = t.reached ? s.targetReached : s.targetMissed;
    d.colour(c, 1.0f, 0.15f);
    const float arm = 5.0f;
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 e(0.0f);
        e[axis] = arm;
        d.segment(t.positionCm - e, t.positionCm + e, 0.7f, 0.7f);
    }
    d.ball(t.positionCm, 1.8f);
    if (t.hasFrom) {
        d.colour(glm::mix(c, glm::vec3(1.0f), 0.3f));
        d.segment(t.fromCm, t.positionCm, 0.35f, 0.35f);
    }
}

void addPinMarker(Drawer& d, const Pin& p, const RenderStyle& s) {
    // A map pin standing on the pinned point, with a small cross at its tip.
    d.colour(s.pin, 1.0f, 0.1f);
    const glm::vec3 tip = p.positionCm;
    d.segment(tip, tip + glm::vec3(0.0f, 12.0f, 0.0f), 0.25f, 1.2f);
    d.ball(tip + glm::vec3(0.0f, 14.0f, 0.0f), 2.6f);
    d.segment(tip + glm::vec3(-3.5f, 0.0f, 0.0f), tip + glm::vec3(3.5f, 0.0f, 0.0f), 0.5f, 0.5f);
    d.segment(tip + glm::vec3(0.0f, 0.0f, -3.5f), tip + glm::vec3(0.0f, 0.0f, 3.5f), 0.5f, 0.5f);
}

void addHeldRing(Drawer& d, const HeldMark& m) {
    // Sixteen short segments around the point, outside the effector's handle ball (4–5 cm): a
    // ring that reads as "held" from above and from the side.
    d.colour(glm::vec3(1.0f, 0.66f, 0.18f), 1.0f, 0.2f);
    constexpr int kSides = 16;
    constexpr float kRadius = 7.5f;
    for (int k = 0; k < kSides; ++k) {
        const float a0 = 6.2831853f * static_cast<float>(k) / kSides,
                    a1 = 6.2831853f * static_cast<float>(k + 1) / kSides;
        d.segment(m.positionCm + kRadius * glm::vec3(std::cos(a0), 0.0f, std::sin(a0)),
                  m.positionCm + kRadius * glm::vec3(std::cos(a1), 0.0f, std::sin(a1)), 0.8f, 0.8f);
    }
}

void addFootprintRosette(Drawer& d, const Footprint& f, float groundHeightCm) {
    // A flat rosette just above the ground (the grid is drawn after the solids and loses the
    // depth test there), in the timeline's contact-lane green: a low rim and eight spokes
    // (segments have no end caps, so a rim alone would read as a thin ring).
    d.colour(glm::vec3(0.30f, 0.78f, 0.42f), 1.0f, 0.25f);
    const glm::vec3 base(f.positionCm.x, groundHeightCm + 0.6f, f.positionCm.z);
    d.segment(base - glm::vec3(0.0f, 0.5f, 0.0f), base + glm::vec3(0.0f, 0.3f, 0.0f), 7.0f, 7.0f);
    for (int k = 0; k < 8; ++k) {
        const float a = 0.785398f * static_cast<float>(k);
        d.segment(base, base + glm::vec3(6.5f * std::cos(a), 0.0f, 6.5f * std::sin(a)), 1.1f, 1.1f);
    }
}

// The opaque solids, collected in draw order: figures, paths (not the on-top ones, nor the still
// overlays when `layered` keeps them in their layer), targets, pins, held rings and footprints.
void addOpaqueSolids(Drawer& d, const Scene& scene, const RenderStyle& s, bool layered) {
    for (const Figure& f : scene.figures)
        if (!f.ghost) d.figure(f, s, false);
    for (const Path& p : scene.paths)
        if (!p.onTop && !(layered && p.stillOverlay)) addScenePath(d, p, s);
    for (const Target& t : scene.targets) addTargetMarker(d, t, s);
    for (const Pin& p : scene.pins) addPinMarker(d, p, s);
    for (const HeldMark& m : scene.heldMarks) addHeldRing(d, m);
    for (const Footprint& f : scene.footprints) addFootprintRosette(d, f, scene.groundHeightCm);
}

enum class GhostSet { kAll, kStillOverlays, kOthers };

// Collects the ghosts of `which` set, in the scene's order.
void addGhosts(Drawer& d, const Scene& scene, const RenderStyle& s, GhostSet which) {
    for (const Figure& f : scene.figures) {
        if (!f.ghost || (which == GhostSet::kStillOverlays && !f.stillOverlay) ||
            (which == GhostSet::kOthers && f.stillOverlay))
            continue;
        d.colour(f.ghostTint, f.ghostAlpha, 0.1f);
        d.figure(f, s, true);
    }
}

// Ghosts, all in one batch: a depth-only pass first, so that each pixel blends only the ghost
// nearest to the eye there, once (onion skins draw several ghosts: two passes in all instead of
// two per ghost). Colour blends as source-over, alpha as premultiplied (an overlay layer keeps it).
void drawCollectedGhosts(Drawer& d) {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    if (!d.empty()) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        d.flush(true);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_EQUAL);
        d.flush();
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LEQUAL);
    }
}

// The pixels a set of world points projects to, grown by 2 (GL's window coordinates); the whole
// frame once a point is behind the eye.
class ScreenBounds {
public:
    ScreenBounds(const glm::mat4& viewProj, int width, int height) : viewProj_(viewProj), w_(width), h_(height) {}
    void add(const glm::vec3& p) {
        if (behind_) return;
        const glm::vec4 clip = viewProj_ * glm::vec4(p, 1.0f);
        if (clip.w <= 1e-4f) {
            behind_ = true;
            return;
        }
        const glm::vec2 px =
            (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(static_cast<float>(w_), static_cast<float>(h_));
        // Within a few screens of the frame: a point just in front of the eye projects far off,
        // and a float past INT_MAX would not convert.
        lo_ = glm::min(lo_, glm::clamp(px, glm::vec2(-1e5f), glm::vec2(1e5f)));
        hi_ = glm::max(hi_, glm::clamp(px, glm::vec2(-1e5f), glm::vec2(1e5f)));
    }
    ScreenRect rect() const {
        if (behind_) return {0, 0, w_, h_};
        if (lo_.x > hi_.x) return {};
        return {std::clamp(static_cast<int>(std::floor(lo_.x)) - 2, 0, w_),
                std::clamp(static_cast<int>(std::floor(lo_.y)) - 2, 0, h_),
                std::clamp(static_cast<int>(std::ceil(hi_.x)) + 2, 0, w_),
                std::clamp(static_cast<int>(std::ceil(hi_.y)) + 2, 0, h_)};
    }

private:
    glm::mat4 viewProj_;
    int w_, h_;
    glm::vec2 lo_{1e30f}, hi_{-1e30f};
    bool behind_ = false;
};

// The window rectangle that holds every collected solid (each point's cube of its radius).
ScreenRect screenRectOf(const Drawer& d, const glm::mat4& viewProj, int width, int height) {
    ScreenBounds bounds(viewProj, width, height);
    auto cover = [&](const glm::vec3& c, float r) {
        for (int corner = 0; corner < 8; ++corner)
            bounds.add(c +
                       r * glm::vec3(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f, corner & 4 ? 1.0f : -1.0f));
    };
    for (const std::vector<Instance>* batch : d.batches())
        for (const Instance& i : *batch) {
            cover(glm::vec3(i.a), i.a.w);
            if (batch == &d.tubes || batch == &d.thinTubes) cover(glm::vec3(i.b), i.b.w);
        }
    return bounds.rect();
}

// A cache key's bytes: `bytes` of `data` appended to `key`.
void appendBytes(std::vector<unsigned char>& key, const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    key.insert(key.end(), b, b + bytes);
}

// What the still overlays' picture is drawn from, as bytes: the view, the size and every instance.
std::vector<unsigned char> overlayKey(const FrameView& view, int width, int height, const Drawer& paths,
                                      const Drawer& ghosts) {
    std::vector<unsigned char> key;
    const auto append = [&key](const void* data, std::size_t bytes) { appendBytes(key, data, bytes); };
    append(&view, sizeof view);
    append(&width, sizeof width);
    append(&height, sizeof height);
    for (const Drawer* d : {&paths, &ghosts})
        for (const std::vector<Instance>* batch : d->batches()) {
            const std::size_t n = batch->size();
            append(&n, sizeof n);
            append(batch->data(), n * sizeof(Instance));
        }
    return key;
}

// What the backdrop's picture is drawn from, as bytes: the view, the size, where the ground is
// and the colours it and the background are drawn in.
std::vector<unsigned char> backdropKey(const Scene& scene, const RenderStyle& s, const FrameView& view, int width,
                                       int height) {
    std::vector<unsigned char> key;
    const auto append = [&key](const void* data, std::size_t bytes) { appendBytes(key, data, bytes); };
    append(&view.viewProj, sizeof view.viewProj);
    append(&width, sizeof width);
    append(&height, sizeof height);
    append(&scene.groundCentreCm, sizeof scene.groundCentreCm);
    append(&scene.groundHeightCm, sizeof scene.groundHeightCm);
    for (const glm::vec3* c : {&s.backgroundTop, &s.backgroundHorizon, &s.ground, &s.gridMinor, &s.gridMajor})
        append(c, sizeof *c);
    append(&s.groundHalfSizeCm, sizeof s.groundHalfSizeCm);
    return key;
}

// The pixels the contact shadows' square on the ground covers (updateShadowTexture's rect),
// grown by 2; all of them when a corner is behind the eye, none without shadows.
ScreenRect shadowScreenRect(const Scene& scene, const glm::vec4& shadowRect, const glm::mat4& viewProj, int width,
                            int height) {
    if (shadowRect.z <= 0.0f) return {};
    const float size = 1.0f / shadowRect.z;
    ScreenBounds bounds(viewProj, width, height);
    for (int corner = 0; corner < 4; ++corner)
        bounds.add(glm::vec3(shadowRect.x + (corner & 1 ? size : 0.0f), scene.groundHeightCm,
                             shadowRect.y + (corner & 2 ? size : 0.0f)));
    return bounds.rect();
}

glm::vec3 handleColourOf(const Handle& h, const RenderStyle& s) {
    switch (h.state) {
        case HandleState::kHover: return s.handleHover;
        case HandleState::kSelected: return s.handleSelected;
        case HandleState::kIdle: break;
    }
    return s.handleIdle;
}

float handleRadiusOf(const Handle& h) { return h.state == HandleState::kSelected ? h.radiusCm * 1.25f : h.radiusCm; }

// Handles: faint where hidden by the body (x-ray), solid where visible.
void drawEffectorHandles(Drawer& d, const Scene& scene, const RenderStyle& s) {
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GREATER);
    for (const Handle& h : scene.handles) {
        d.colour(handleColourOf(h, s), h.state == HandleState::kIdle ? 0.15f : 0.3f, 0.5f);
        d.ball(h.positionCm, handleRadiusOf(h));
    }
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    for (const Handle& h : scene.handles) {
        const float emissive = h.state == HandleState::kIdle ? 0.15f : 0.55f;
        d.colour(handleColourOf(h, s), h.state == HandleState::kIdle ? 0.75f : 0.95f, emissive);
        d.ball(h.positionCm, handleRadiusOf(h));
    }
    d.flush();
}

// Paths drawn over everything (a gizmo): a fresh depth buffer, so that they hide only themselves.
void drawOnTopPaths(Drawer& d, const Scene& scene, const RenderStyle& s) {
    bool anyOnTop = false;
    for (const Path& p : scene.paths) anyOnTop = anyOnTop || p.onTop;
    if (anyOnTop) {
        glDisable(GL_BLEND);
        glClear(GL_DEPTH_BUFFER_BIT);
        for (const Path& p : scene.paths)
            if (p.onTop) addScenePath(d, p, s);
        d.flush();
        glEnable(GL_BLEND);
    }
}

// The caption's glyph quads (stb_easy_font) as triangles of (x, y, 0) in text pixels.
std::vector<float> captionTriangles(const std::string& caption) {
    std::vector<char> buffer(64 * 1024);
    std::string text = caption;
    const int quads =
        stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
    std::vector<float> tris;
    tris.reserve(static_cast<std::size_t>(quads) * 18);
    for (int q = 0; q < quads; ++q) {
        const float* v = reinterpret_cast<const float*>(buffer.data() + q * 64);
        const int order[6] = {0, 1, 2, 0, 2, 3};
        for (int k : order) tris.insert(tris.end(), {v[k * 4 + 0], v[k * 4 + 1], 0.0f});
    }
    return tris;
}

}  // namespace

void SceneRenderer::Impl::beginFrame(const RenderStyle& s, int width, int height, unsigned targetFramebuffer) {
    // With MSAA the frame goes through the renderer's multisampled framebuffer; without it, straight
    // into the target (which must then have a depth buffer, as the pbuffer and GLFW windows do).
    const bool msaa = samples > 1;
    if (msaa) ensureFramebuffer(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, msaa ? fbo : targetFramebuffer);
    setFrameState(width, height);
    glClearColor(s.backgroundHorizon.r, s.backgroundHorizon.g, s.backgroundHorizon.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void SceneRenderer::Impl::setFrameState(int width, int height) {
    glViewport(0, 0, width, height);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
}

// The frame starts as a copy of the backdrop (ground without shadows, background), drawn into its
// layer first when the view, the size, the ground or the style changed.
bool SceneRenderer::Impl::beginFrameFromBackdrop(const Scene& scene, const RenderStyle& s, const FrameView& view,
                                                 int width, int height, unsigned targetFramebuffer) {
    std::vector<unsigned char> key = backdropKey(scene, s, view, width, height);
    if (!backdrop->holds(key)) {
        // A view that changes every frame (playback following the character, an orbit) would pay
        // for the layer and the copy each time: only a view seen twice in a row is kept.
        if (key != backdropCandidate) {
            backdropCandidate = std::move(key);
            return false;
        }
        backdrop->beginDraw(width, height, s.backgroundHorizon.r, s.backgroundHorizon.g, s.backgroundHorizon.b);
        setFrameState(width, height);
        useLit(view);  // the depth test and blending the ground is drawn with
        const float viewportHeight = static_cast<float>(height);
        drawGround(scene, s, view.viewProj, viewportHeight, glm::vec4(0.0f));
        drawBackground(s, viewportHeight);
        backdrop->endDraw(std::move(key));
    }
    backdrop->copyInto(targetFramebuffer);
    setFrameState(width, height);
    return true;
}

void SceneRenderer::Impl::useLit(const FrameView& view) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_BLEND);
    lit.use();
    lit.set("uViewProj", view.viewProj);
    lit.set("uEye", view.eye);
    lit.set("uKeyDir", view.keyDir);
    lit.set("uFillDir", view.fillDir);
}

void SceneRenderer::Impl::drawGround(const Scene& scene, const RenderStyle& s, const glm::mat4& viewProj,
                                     float viewportHeight, const glm::vec4& shadowRect) {
    const glm::vec3 focus(scene.groundCentreCm.x, scene.groundHeightCm, scene.groundCentreCm.z);
    const glm::vec3 centre(std::round(focus.x / 100.0f) * 100.0f, scene.groundHeightCm,
                           std::round(focus.z / 100.0f) * 100.0f);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, shadowTexture);
    ground.use();
    ground.set("uViewProj", viewProj);
    ground.set("uCentre", centre);
    ground.set("uHalfSize", s.groundHalfSizeCm);
    ground.set("uGround", s.ground);
    ground.set("uMinor", s.gridMinor);
    ground.set("uMajor", s.gridMajor);
    ground.set("uFocus", focus);
    ground.set("uFadeRadius", s.groundHalfSizeCm);
    ground.set("uShadow", 0);
    ground.set("uShadowRect", shadowRect);
    ground.set("uTop", s.backgroundTop);
    ground.set("uHorizon", s.backgroundHorizon);
    ground.set("uViewportHeight", viewportHeight);
    quad.draw();
}

void SceneRenderer::Impl::drawBackground(const RenderStyle& s, float viewportHeight) {
    background.use();
    background.set("uTop", s.backgroundTop);
    background.set("uHorizon", s.backgroundHorizon);
    background.set("uViewportHeight", viewportHeight);
    glDepthMask(GL_FALSE);
    glBindVertexArray(emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
}

void SceneRenderer::Impl::drawCaption(const std::string& caption, int width, int height) {
    const std::vector<float> tris = captionTriangles(caption);
    const float scale = height >= 400 ? 2.0f : 1.0f;
    const float textHeight = 8.0f * scale;
    glDisable(GL_DEPTH_TEST);
    text.use();
    text.set("uViewport", glm::vec2(static_cast<float>(width), static_cast<float>(height)));
    text.set("uScale", scale);
    glBindVertexArray(textVao);
    glBindBuffer(GL_ARRAY_BUFFER, textVbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(tris.size() * sizeof(float)), tris.data(), GL_STREAM_DRAW);
    const glm::vec2 origin(8.0f * scale, static_cast<float>(height) - textHeight - 6.0f * scale);
    text.set("uOffset", origin + glm::vec2(scale, scale));
    text.set("uColour", glm::vec4(0.0f, 0.0f, 0.0f, 0.6f));
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(tris.size() / 3));
    text.set("uOffset", origin);
    text.set("uColour", glm::vec4(0.95f, 0.95f, 0.95f, 1.0f));
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(tris.size() / 3));
    glEnable(GL_DEPTH_TEST);
}

void SceneRenderer::Impl::resolveFrame(int width, int height, unsigned targetFramebuffer) {
    if (samples > 1) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetFramebuffer);
        glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targetFramebuffer);
}

// The still overlays (trails away from the current frame, onion skins) through their cached layer:
// drawn into it only when their content or the view changed, then laid into the frame by depth.
void SceneRenderer::Impl::drawStillOverlays(const Scene& scene, const RenderStyle& s, const FrameView& view, int width,
                                            int height, unsigned targetFramebuffer) {
    Drawer paths{lit, sphere, smallSphere, tinySphere, tube, thinTube,        instanceVbo,
                 {},  {},     {},          {},         {},   glm::vec4(1.0f), 0.0f};
    Drawer ghosts = paths;
    for (const Path& p : scene.paths)
        if (p.stillOverlay && !p.onTop) addScenePath(paths, p, s);
    addGhosts(ghosts, scene, s, GhostSet::kStillOverlays);
    if (paths.empty() && ghosts.empty()) return;  // nothing still in this scene: the layer stays as it was
    std::vector<unsigned char> key = overlayKey(view, width, height, paths, ghosts);
    if (!stillOverlays->holds(key)) {
        ScreenRect rect = screenRectOf(paths, view.viewProj, width, height);
        const ScreenRect ghostRect = screenRectOf(ghosts, view.viewProj, width, height);
        if (rect.empty())
            rect = ghostRect;
        else if (!ghostRect.empty())
            rect = {std::min(rect.x0, ghostRect.x0), std::min(rect.y0, ghostRect.y0), std::max(rect.x1, ghostRect.x1),
                    std::max(rect.y1, ghostRect.y1)};
        stillOverlays->beginDraw(width, height);
        useLit(view);
        paths.flush();
        drawCollectedGhosts(ghosts);
        stillOverlays->endDraw(std::move(key), rect);
        glBindFramebuffer(GL_FRAMEBUFFER, targetFramebuffer);
        glViewport(0, 0, width, height);
    }
    stillOverlays->composite();
}

void SceneRenderer::draw(const Scene& scene, const OrbitCamera& camera, int width, int height,
                         unsigned targetFramebuffer) {
    Impl& r = *impl_;
    const RenderStyle& s = style_;
    // 1. The frame: target, state, clear (or the backdrop's copy).
    const FrameView view = frameViewOf(camera, width, height);
    const bool fromBackdrop =
        r.backdrop && scene.showGround && r.beginFrameFromBackdrop(scene, s, view, width, height, targetFramebuffer);
    if (!fromBackdrop) r.beginFrame(s, width, height, targetFramebuffer);

    // 2. Opaque solids: figures, paths, targets, pins.
    r.useLit(view);
    Drawer d{r.lit, r.sphere, r.smallSphere,   r.tinySphere, r.tube, r.thinTube, r.instanceVbo, {}, {}, {},
             {},    {},       glm::vec4(1.0f), 0.0f};
    // Without MSAA the still overlays go through their cached layer (step 5).
    const bool layered = r.stillOverlays != nullptr;
    addOpaqueSolids(d, scene, s, layered);
    d.flush();

    // 3. Ground with grid and contact shadows, after the solids so their pixels are depth-rejected.
    // It is opaque and fades into the background gradient by itself.
    // From the backdrop, only the square under the contact shadows is shaded again (the same
    // fragments at the same depth, now with their shadow).
    const float viewportHeight = static_cast<float>(height);
    if (scene.showGround) {
        const glm::vec4 shadowRect = r.updateShadowTexture(scene);
        const ScreenRect patch = fromBackdrop ? shadowScreenRect(scene, shadowRect, view.viewProj, width, height)
                                              : ScreenRect{0, 0, width, height};
        if (!patch.empty()) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(patch.x0, patch.y0, patch.x1 - patch.x0, patch.y1 - patch.y0);
            r.drawGround(scene, s, view.viewProj, viewportHeight, shadowRect);
            glDisable(GL_SCISSOR_TEST);
        }
    }

    // 4. Background gradient on the far plane: only the pixels nothing has covered are shaded.
    if (!fromBackdrop) r.drawBackground(s, viewportHeight);

    // 5. The still overlays' layer, ghosts (blended), 6. handles, 6b. paths drawn on top.
    if (layered) r.drawStillOverlays(scene, s, view, width, height, targetFramebuffer);
    r.lit.use();  // the passes below draw solids again
    addGhosts(d, scene, s, layered ? GhostSet::kOthers : GhostSet::kAll);
    drawCollectedGhosts(d);
    drawEffectorHandles(d, scene, s);
    drawOnTopPaths(d, scene, s);

    // 7. Caption (screen space, stb_easy_font, with a 1-pixel shadow).
    if (!scene.caption.empty()) r.drawCaption(scene.caption, width, height);
    glBindVertexArray(0);
    glDisable(GL_BLEND);

    // 8. Resolve the multisampled frame into the target framebuffer.
    r.resolveFrame(width, height, targetFramebuffer);
}

}  // namespace mgp::render
