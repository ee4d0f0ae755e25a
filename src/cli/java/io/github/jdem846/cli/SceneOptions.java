package io.github.jdem846.cli;

import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.io.IOException;
import java.io.PrintWriter;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * What a shaded relief looks like, for {@code render} and {@code tiles}: the tint, the hillshade method and its
 * knobs, the cast shadows and their options, listed in this order.
 */
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
                .withShadowIntensity(shadowIntensity);
    }
}
