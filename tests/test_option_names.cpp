// The one table of option names (option_names.hpp): every name reaches the
// field it names, aliases give the same options, bad names are errors that
// list the choices, and the printed name reads back.
#include <catch2/catch.hpp>

#include "phongrast/option_names.hpp"

using Catch::Matchers::Contains;
using namespace phongrast;

TEST_CASE("each named option sets its field, over the mode's preset") {
    RenderOptions options = options_from_names({{"mode", "seed"}, {"visibility", "depth-buffer"}, {"overdraw", "visible"},
                                                {"precision", "double"}, {"sample_pattern", "rotated"},
                                                {"back_faces", "cull"}, {"texture_filter", "trilinear"}});
    const RenderOptions seed = RenderOptions::seed();
    CHECK(options.light_vectors == seed.light_vectors);
    CHECK(options.interpolation == seed.interpolation);
    CHECK(options.border == seed.border);
    CHECK(options.visibility == Visibility::depth_buffer);
    CHECK(options.overdraw == Overdraw::shade_visible);
    CHECK(options.precision == Precision::double_float);
    CHECK(options.sample_pattern == SamplePattern::rotated_grid);
    CHECK(options.back_faces == BackFaces::cull_when_hidden);
    CHECK(options.texture_filter == TextureFilter::trilinear);

    options = options_from_names({{"texture_filter", "nearest"}, {"overdraw", "all"}});
    CHECK(options.texture_filter == TextureFilter::nearest);
    CHECK(options.overdraw == Overdraw::shade_all);
    CHECK(options.light_vectors == RenderOptions::exact().light_vectors);
}

TEST_CASE("no names, or empty ones, give the exact preset's defaults") {
    const RenderOptions options = options_from_names({{"visibility", ""}, {"mode", ""}});
    const RenderOptions exact = RenderOptions::exact();
    CHECK(options.visibility == exact.visibility);
    CHECK(options.overdraw == exact.overdraw);
    CHECK(options.texture_filter == TextureFilter::bilinear);
    CHECK(options.light_vectors == exact.light_vectors);
    for (const NamedOption& option : named_options()) {
        INFO(option.key);
        CHECK(option_name(exact, option.key) == option.default_name);
    }
}

TEST_CASE("depth-buffer and depth_buffer are one name, keys may be spelled as flags") {
    CHECK(options_from_names({{"visibility", "depth_buffer"}}).visibility == Visibility::depth_buffer);
    CHECK(options_from_names({{"--visibility", "depth-buffer"}}).visibility == Visibility::depth_buffer);
    CHECK(options_from_names({{"sample-pattern", "rotated"}}).sample_pattern == SamplePattern::rotated_grid);
    const std::vector<std::string> names = accepted_names(named_option("visibility"));
    CHECK(names == std::vector<std::string>{"painter", "depth-buffer", "depth_buffer"});
    CHECK(option_flag(named_option("texture_filter")) == "--texture-filter");
}

TEST_CASE("a bad name or key is an error naming it and listing the choices") {
    CHECK_THROWS_WITH(options_from_names({{"visibility", "zbuffer"}}),
                      Contains("visibility: unknown 'zbuffer'; expected 'painter' or 'depth-buffer'"));
    CHECK_THROWS_WITH(options_from_names({{"texture_filter", "cubic"}}),
                      Contains("texture_filter: unknown 'cubic'; expected 'bilinear', 'nearest' or 'trilinear'"));
    CHECK_THROWS_WITH(options_from_names({{"mode", "fast"}}), Contains("mode: unknown 'fast'; expected 'exact' or 'seed'"));
    CHECK_THROWS_WITH(options_from_names({{"colour", ""}}), Contains("unknown option 'colour'; expected one of mode,"));
    RenderOptions options;
    CHECK_THROWS_AS(set_named_option(options, "overdraw", "none"), std::invalid_argument);
}

TEST_CASE("the printed name of every choice reads back to the same options") {
    for (const NamedOption& option : named_options()) {
        for (const auto& choice : option.choices) {
            for (const std::string& spelling : choice) {
                INFO(option.key << " = " << spelling);
                RenderOptions options = RenderOptions::exact();
                set_named_option(options, option.key, spelling);
                CHECK(option_name(options, option.key) == choice.front());
            }
        }
    }
    CHECK(option_name(RenderOptions::seed(), "mode") == "seed");
}
