// The procedural benchmark scenes have the geometry their names promise:
// ray-traced V_R (at each scene's own AO radius) is low where the scene is
// meant to be hard and near 1 on open floor beside it.
#include "raytracer.h"
#include "scene.h"

#include <doctest/doctest.h>

#include <string>

namespace {

struct Loaded {
    scene::Scene sc;
    float radius = 0;
};

Loaded load(const char* name) {
    Loaded l;
    std::string error;
    REQUIRE_MESSAGE(scene::load(std::string(SSAO_TEST_ASSETS_DIR) + "/scenes/" + name, l.sc, error), error);
    const auto r = scene::ao_radius(l.sc);
    REQUIRE(r);
    l.radius = r->radius;
    return l;
}

// V_R at a point on an upward-facing floor or top.
double v_up(const raytrace::Tracer& t, glm::vec3 p, float radius) {
    return t.ao_at(p, {0, 1, 0}, radius, 4096, 3).visibility;
}

}  // namespace

TEST_SUITE("scenes") {

TEST_CASE("each scene is small, has its own camera and an AO radius hint") {
    struct Expected {
        const char* name;
        float radius;
    };
    for (const Expected& e : {Expected{"overhang.gltf", 0.4f}, Expected{"creases.gltf", 0.25f},
                              Expected{"clutter.gltf", 0.4f}}) {
        const char* name = e.name;
        const float radius = e.radius;
        CAPTURE(name);
        const Loaded l = load(name);
        CHECK(l.sc.mesh.triangle_count() >= 100);
        CHECK(l.sc.mesh.triangle_count() <= 3000);
        CHECK(l.sc.camera.has_value());
        CHECK(l.radius == doctest::Approx(radius));
    }
}

TEST_CASE("overhang: dark contact shadows under the table and the bench, open floor beside them") {
    const Loaded l = load("overhang.gltf");
    raytrace::Tracer t(l.sc.mesh);
    REQUIRE(t.ok());
    const double under_table = v_up(t, {0.0f, 0.0f, 0.0f}, l.radius);
    const double under_bench = v_up(t, {-0.2f, 0.0f, 1.45f}, l.radius);
    const double under_shelf = v_up(t, {1.5f, 0.0f, -2.7f}, 2.0f * l.radius);
    const double open_floor = v_up(t, {2.2f, 0.0f, 2.2f}, l.radius);
    CAPTURE(under_table);
    CAPTURE(under_bench);
    CAPTURE(under_shelf);
    CHECK(under_table < 0.5);   // the table top 0.25 above covers most of the hemisphere within R = 0.4
    CHECK(under_bench < 0.25);  // the bench slab 0.12 above
    CHECK(under_shelf < 0.6);   // the shelf 0.5 above, at the 2x radius
    CHECK(open_floor > 0.99);
    // On the table top nothing is above: the contrast is the overhang, not the floor.
    CHECK(v_up(t, {0.0f, 0.32f, 0.0f}, l.radius) > 0.99);
}

TEST_CASE("creases: narrow grooves and stair corners are deep at the scene's radius") {
    const Loaded l = load("creases.gltf");
    raytrace::Tracer t(l.sc.mesh);
    REQUIRE(t.ok());
    // The bottom of a groove between two ribs (0.04 wide, 0.1 deep).
    const double groove = v_up(t, {0.06f, 0.05f, -1.0f}, l.radius);
    // The inner corner at the foot of the second riser, on the first tread.
    const double stair = v_up(t, {-1.2f, 0.12f, -0.41f}, l.radius);
    // The bottom of a fold of the accordion (between two slopes rising 0.12 over 0.075).
    const double fold = v_up(t, {-0.45f, 0.0005f, 0.75f}, l.radius);
    CAPTURE(groove);
    CAPTURE(stair);
    CAPTURE(fold);
    CHECK(groove < 0.25);
    CHECK(stair < 0.8);
    CHECK(fold < 0.6);
    CHECK(v_up(t, {1.5f, 0.0f, 1.5f}, l.radius) > 0.99);
}

TEST_CASE("clutter: objects against two walls and each other") {
    const Loaded l = load("clutter.gltf");
    raytrace::Tracer t(l.sc.mesh);
    REQUIRE(t.ok());
    // Floor beside the crate pushed into the corner, 0.05 from its side.
    const double crate_corner = v_up(t, {-2.05f, 0.0f, -2.5f}, l.radius);
    // Behind the leaning board, where it meets the wall and the floor.
    const double behind_board = v_up(t, {2.3f, 0.0f, -2.95f}, l.radius);
    // Beside the octagonal column.
    const double column = v_up(t, {1.4f, 0.0f, -1.4f}, l.radius);
    // The corner where the two walls meet the floor.
    const double room_corner = v_up(t, {-2.95f, 0.15f, 1.55f}, l.radius);
    CAPTURE(crate_corner);
    CAPTURE(behind_board);
    CAPTURE(column);
    CAPTURE(room_corner);
    CHECK(crate_corner < 0.8);
    CHECK(behind_board < 0.4);
    CHECK(column < 0.9);
    CHECK(room_corner < 0.9);
    CHECK(v_up(t, {1.0f, 0.0f, 2.0f}, l.radius) > 0.99);
}

}  // TEST_SUITE
