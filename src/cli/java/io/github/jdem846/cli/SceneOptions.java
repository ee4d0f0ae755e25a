package io.github.jdem846.cli;

import io.github.jdem846.render.Blend;
import io.github.jdem846.render.BlendMode;
import io.github.jdem846.render.LightModel;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.SkyViewOptions;
import java.io.IOException;
import java.io.PrintWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * What a shaded relief looks like, for {@code render} and {@code tiles}: the tint, the hillshade method and its
 * knobs, the cast shadows and their options, listed in this order.
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class SceneOptions {

    @Mixin
    TintOptions tint;

    @Option(names = "--hillshade", paramLabel = "METHOD", defaultValue = "jdem846",
            converter = Converters.HillshadeOrNone.class,
            description = "jdem846 (the article's, default), horn, multidirectional, combined, igor or none.")
    HillshadeMethod method;

    @Mixin
    ShadingOptions shading;

    /** Tiles words this one its own way: picocli looks its description up by this key in the command's bundle. */
    @Option(names = "--shadows", paramLabel = "ALGORITHM", defaultValue = "none", descriptionKey = "shadows",
            converter = Converters.Algorithm.class,
            description = "Cast shadows: none (default), sweep (fast, O(cells)), march (the article's ray march, "
                    + "fixed) or exact (the slow reference).")
    ShadowAlgorithm algorithm;

    @Option(names = "--shadow-intensity", paramLabel = "0..1", defaultValue = "0.4",
            converter = Converters.ShadowIntensity.class,
            description = "A cell in cast shadow loses 2 × this much brightness, 0 to 1. Default: ${DEFAULT-VALUE}.")
    double shadowIntensity;

    @Mixin
    ShadowCliOptions shadowOptions;

    @Option(names = "--light-model", paramLabel = "MODEL", defaultValue = "jdem846",
            converter = Converters.LightModelName.class,
            description = "How sun, cast shadows and sky light combine: jdem846 (the original's, default: a cast "
                    + "shadow darkens by a fixed amount) or sky (direct sun × (1 − shadow) + ambient × sky-view "
                    + "factor: shaded terrain lit by the sky it sees).")
    LightModel lightModel;

    @Option(names = "--ambient", paramLabel = "0..1", converter = Converters.Ambient.class,
            description = "Weight of the light of the sky, lighting each cell by the share of the sky it sees "
                    + "(sky-view factor); 0 computes no sky view. Default: " + LightModel.SKY_AMBIENT
                    + " with --light-model sky, 0 with jdem846.")
    Double ambient;

    @Option(names = "--blend", paramLabel = "MODE", defaultValue = "jdem846",
            converter = Converters.BlendModeName.class,
            description = "How the shading is laid on the tint: jdem846 (eq. 8, the original's, default), "
                    + "jdem846-lighten or jdem846-darken (the original's other two: shading only lightens or only "
                    + "darkens), or a gray hillshade blended as in QGIS: multiply, screen, overlay, soft-light.")
    BlendMode blend;

    @Option(names = "--hillshade-opacity", paramLabel = "0..1", defaultValue = "1",
            converter = Converters.HillshadeOpacity.class,
            description = "Weight of the shaded colour against the bare tint (the original's era-A lighting "
                    + "multiple, 0.75 there), 0 to 1. Default: ${DEFAULT-VALUE}.")
    double hillshadeOpacity;

    @Option(names = "--sky-directions", paramLabel = "D", defaultValue = "32",
            converter = Converters.SkyDirections.class,
            description = "Azimuths of the sky-view factor's horizons, 4 to 360. Default: ${DEFAULT-VALUE}.")
    int skyDirections;

    @Option(names = "--sky-radius", paramLabel = "METRES", converter = Converters.SkyRadius.class,
            description = "Search the sky-view factor's horizons within this many metres of each cell (terrain "
                    + "farther away does not count), as WhiteboxTools' and RVT's maximum search distance. "
                    + "Default: the whole grid.")
    Double skyRadius;

    /** Says on {@code err} when a shadow option given has no effect with the shadows chosen. */
    void noteUnused(PrintWriter err) {
        shadowOptions.noteUnused(algorithm, err);
    }

    /** True when {@code --xy-scale} was given. */
    boolean xyScaleGiven() {
        return shading.xyScale != null;
    }

    /**
     * The scene these options describe.
     *
     * @throws picocli.CommandLine.ParameterException when the tint options do not go together or name no ramp
     * @throws IOException                            when a colour file cannot be read
     */
    Scene scene() throws IOException {
        return Scene.defaults().withTint(tint.ramp()).withHillshade(method).withHillshadeOptions(shading.options())
                .withShadows(algorithm).withShadowOptions(shadowOptions.options())
                .withShadowIntensity(shadowIntensity).withLightModel(lightModel)
                .withAmbient(ambient != null ? ambient : lightModel == LightModel.SKY ? LightModel.SKY_AMBIENT : 0)
                .withSkyDirections(skyDirections)
                .withSkyRadius(skyRadius != null ? skyRadius : SkyViewOptions.UNBOUNDED)
                .withBlend(new Blend(blend, hillshadeOpacity));
    }
}
