// test_threads.cpp - the header's promise that distinct contexts work from
// distinct threads, each with its own GL context: two threads, two
// EGL contexts, 1,000 executes each with changing settings and viewports, and
// every frame's AO identical to the same sequence run on one thread.
// Both threads wait at a barrier after creating their contexts, then run
// their sequences side by side; each asks for shader variants the other does
// not (distance fade and frame noise in one, pixel radius in the other).
// The executes take turns (a process-wide lock held from execute to
// glFinish): Mesa 22.3's llvmpipe crashes (SIGSEGV inside swrast_dri.so) in
// about one run in four when two contexts draw at once, with the library of
// an earlier commit too, and never in 16 runs with the draws taking turns.
// Context creation, set_settings, readbacks and destruction still overlap,
// and each thread's GL context stays current on its own thread throughout.
// SSAO_TEST_CONCURRENT_EXECUTES=1 lets the executes overlap as well, for a
// driver that draws from several contexts at once.
// scripts/run-sanitizers.sh also runs it under ThreadSanitizer.
#include "gl_fixture.h"
#include "test_scenes.h"

#include <doctest/doctest.h>

#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr int kW = 24, kH = 18;
constexpr int kExecutes = 1000;

// FNV-1a over the AO bits of one frame.
uint64_t hash_floats(const std::vector<float>& v) {
    uint64_t h = 1469598103934665603ull;
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    for (size_t i = 0; i < v.size() * sizeof(float); ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

// Releases its threads together once `count` have arrived (C++17 has no std::barrier).
class Barrier {
public:
    explicit Barrier(int count) : left_(count) {}
    void arrive_and_wait() {
        std::unique_lock<std::mutex> lock(mutex_);
        if (--left_ == 0) {
            released_.notify_all();
            return;
        }
        released_.wait(lock, [&] { return left_ == 0; });
    }

private:
    std::mutex mutex_;
    std::condition_variable released_;
    int left_;
};

// Whether the two threads' executes may overlap (see the top of the file).
bool concurrent_executes() {
    const char* v = std::getenv("SSAO_TEST_CONCURRENT_EXECUTES");
    return v != nullptr && std::strcmp(v, "1") == 0;
}

std::mutex g_execute_turn;  // held by the thread whose execute runs, unless they may overlap

struct Run {
    std::vector<uint64_t> frames;  // one hash per execute
    std::string error;             // first failure, empty if none
    size_t gl_errors = 0;
};

// One thread's whole life: its own EGL context, plugin context and textures,
// `kExecutes` frames of a sequence that depends on `seed` (1 or 2: each asks
// for shader variants of its own). With a barrier, the first execute waits
// there until the other thread is ready for its own first execute too.
Run run_sequence(int seed, Barrier* start = nullptr) {
    Run r;
    bool arrived = false;
    try {
        using namespace testscenes;
        testgl::Fixture fx;  // EGL context current on this thread, plugin context on it
        const auto proj = analytic::perspective(kFov, double(kW) / kH, 0.1, 100.0);
        const analytic::GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
        const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, kW, kH, g.depth);
        const GLuint normal = fx.make_normals(GL_RGBA16F, kW, kH, g.normal);
        const ssao_inputs base = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        const ssao_blur blurs[] = {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN};
        const bool overlap = concurrent_executes();
        for (int i = 0; i < kExecutes; ++i) {
            const int step = seed * 7919 + i;
            if (i % 10 == 0) {
                ssao_settings s{};
                s.size = sizeof s;
                s.sample_count = static_cast<uint32_t>(1 + (step * 13) % 32);
                s.radius = 0.3f + 0.05f * static_cast<float>(step % 11);
                s.blur = blurs[(step / 10) % 4];
                s.seed = static_cast<uint32_t>(seed + 1);
                s.output_format = (step / 20) % 2 ? SSAO_OUTPUT_R16F : SSAO_OUTPUT_R8;
                if (seed == 1) {  // the FADE variant
                    s.fade_start = 2.0f;
                    s.fade_end = 8.0f;
                } else {          // the RADIUS_PIXELS variant
                    s.radius_pixels = 6.0f;
                }
                if (fx.api().set_settings(fx.ctx(), &s) != SSAO_OK) throw std::runtime_error("set_settings failed");
            }
            ssao_inputs in = base;
            if (seed == 1) in.frame_index = static_cast<uint32_t>(i + 1);  // the FRAME_NOISE variant
            if (start && !arrived) {
                arrived = true;
                start->arrive_and_wait();
            }
            const int w = 1 + (step * 5) % kW, h = 1 + (step * 3) % kH;
            in.viewport[0] = (step % (kW - w + 1));
            in.viewport[1] = (step % (kH - h + 1));
            in.viewport[2] = w;
            in.viewport[3] = h;
            ssao_output out{};
            out.size = sizeof out;
            std::unique_lock<std::mutex> turn(g_execute_turn, std::defer_lock);
            if (!overlap) turn.lock();
            if (fx.api().execute(fx.ctx(), &in, &out) != SSAO_OK)
                throw std::runtime_error(std::string("execute: ") + fx.api().last_error(fx.ctx()));
            fx.gl().Finish();  // the draws done before the other thread's turn
            if (turn.owns_lock()) turn.unlock();
            r.frames.push_back(hash_floats(fx.read_red(out.texture, w, h)));
        }
        r.gl_errors = fx.gl_errors().size();
    } catch (const std::exception& e) {
        r.error = e.what();
    }
    if (start && !arrived) start->arrive_and_wait();  // failed before its first execute: do not strand the other
    return r;
}

}  // namespace

TEST_CASE("threads: two contexts on two threads give the single-threaded results, frame for frame") {
    // Together first: the driver's first shader compiles in this process
    // (its one-time set-up included) happen in both threads at once.
    Run together_a, together_b;
    Barrier start(2);
    std::thread ta([&] { together_a = run_sequence(1, &start); });
    std::thread tb([&] { together_b = run_sequence(2, &start); });
    ta.join();
    tb.join();
    REQUIRE_MESSAGE(together_a.error.empty(), together_a.error);
    REQUIRE_MESSAGE(together_b.error.empty(), together_b.error);
    CHECK(together_a.gl_errors == 0u);
    CHECK(together_b.gl_errors == 0u);

    // The oracle: both sequences, one after the other, on this thread.
    const Run alone_a = run_sequence(1);
    const Run alone_b = run_sequence(2);
    REQUIRE_MESSAGE(alone_a.error.empty(), alone_a.error);
    REQUIRE_MESSAGE(alone_b.error.empty(), alone_b.error);
    REQUIRE(alone_a.frames.size() == size_t(kExecutes));
    CHECK(alone_a.frames != alone_b.frames);  // the sequences differ, so a mix-up would show
    int differing = 0;
    for (int i = 0; i < kExecutes; ++i) {
        differing += together_a.frames[size_t(i)] != alone_a.frames[size_t(i)];
        differing += together_b.frames[size_t(i)] != alone_b.frames[size_t(i)];
    }
    CHECK(differing == 0);
}
