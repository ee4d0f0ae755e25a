package io.github.jdem846.cli;

import io.github.jdem846.shade.HillshadeOptions;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The hillshade knobs with the original's defaults: z-factor, light multiple, intensities, spot exponent. Each value
 * is checked as it is parsed by {@link HillshadeOptions}, which holds the ranges.
 */
public final class ShadingOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    private HillshadeOptions options = HillshadeOptions.DEFAULTS;

    @Option(names = {"-z", "--z-factor"}, paramLabel = "FACTOR", defaultValue = "1",
            description = "Vertical exaggeration: above 0, at most 1000000 (gdaldem's -z also takes 0 and negative "
                    + "factors, which flatten or invert the relief). Default: ${DEFAULT-VALUE}.")
    void zFactor(double z) {
        Usage.check(command, "--z-factor", () -> options = options.withZFactor(z));
    }

    @Option(names = "--light-multiple", paramLabel = "FACTOR", defaultValue = "0.75",
            description = "jdem846 method: heights are scaled by this for the normals only; 0 to 1000000. "
                    + "Default: ${DEFAULT-VALUE}.")
    void lightMultiple(double m) {
        Usage.check(command, "--light-multiple", () -> options = options.withLightMultiple(m));
    }

    @Option(names = "--light-intensity", paramLabel = "0..1", defaultValue = "0.75",
            description = "Relative light intensity (scales lit slopes), 0 to 1. Default: ${DEFAULT-VALUE}.")
    void lightIntensity(double light) {
        Usage.check(command, "--light-intensity", () -> options = options.withIntensities(light,
                options.relativeDarkIntensity()));
    }

    @Option(names = "--dark-intensity", paramLabel = "0..1", defaultValue = "1.0",
            description = "Relative dark intensity (scales shaded slopes), 0 to 1. Default: ${DEFAULT-VALUE}.")
    void darkIntensity(double dark) {
        Usage.check(command, "--dark-intensity", () -> options = options.withIntensities(
                options.relativeLightIntensity(), dark));
    }

    @Option(names = "--spot-exponent", paramLabel = "EXP", defaultValue = "1",
            description = "Sign-preserving exponent on the brightness, 0.01 to 128. Default: ${DEFAULT-VALUE}.")
    void spotExponent(double spot) {
        Usage.check(command, "--spot-exponent", () -> options = options.withSpotExponent(spot));
    }

    @Option(names = {"-s", "--xy-scale"}, paramLabel = "UNITS_TO_METRES",
            description = "Like gdaldem -s: horizontal cell size = CRS units × this (e.g. 111120 for degrees); a "
                    + "finite number above 0. Default: the true metric cell size from the CRS, per row for lat/lon "
                    + "grids.")
    void xyScale(double scale) {
        if (Double.isNaN(scale)) { // the library's "not given"
            throw Usage.invalid(command, "the horizontal scale must be a finite number above 0, got NaN",
                    "--xy-scale");
        }
        Usage.check(command, "--xy-scale", () -> options = options.withHorizontalScale(scale));
    }

    /** The options record. */
    HillshadeOptions options() {
        return options;
    }
}
