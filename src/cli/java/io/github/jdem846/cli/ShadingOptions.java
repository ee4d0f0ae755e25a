package io.github.jdem846.cli;

import io.github.jdem846.shade.HillshadeOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The hillshade knobs with the original's defaults: z-factor, light multiple, intensities, spot exponent. Each value
 * is checked as it is parsed against the ranges of {@link HillshadeOptions}.
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class ShadingOptions {

    @Option(names = {"-z", "--z-factor"}, paramLabel = "FACTOR", defaultValue = "1",
            converter = Converters.ZFactor.class,
            description = "Vertical exaggeration: above 0, at most 1000000 (gdaldem's -z also takes 0 and negative "
                    + "factors, which flatten or invert the relief). Default: ${DEFAULT-VALUE}.")
    double zFactor;

    @Option(names = "--light-multiple", paramLabel = "FACTOR", defaultValue = "0.75",
            converter = Converters.LightMultiple.class,
            description = "jdem846 method: heights are scaled by this for the normals only; 0 to 1000000. "
                    + "Default: ${DEFAULT-VALUE}.")
    double lightMultiple;

    @Option(names = "--light-intensity", paramLabel = "0..1", defaultValue = "0.75",
            converter = Converters.LightIntensity.class,
            description = "Relative light intensity (scales lit slopes), 0 to 1. Default: ${DEFAULT-VALUE}.")
    double lightIntensity;

    @Option(names = "--dark-intensity", paramLabel = "0..1", defaultValue = "1.0",
            converter = Converters.DarkIntensity.class,
            description = "Relative dark intensity (scales shaded slopes), 0 to 1. Default: ${DEFAULT-VALUE}.")
    double darkIntensity;

    @Option(names = "--spot-exponent", paramLabel = "EXP", defaultValue = "1",
            converter = Converters.SpotExponent.class,
            description = "Sign-preserving exponent on the brightness, 0.01 to 128. Default: ${DEFAULT-VALUE}.")
    double spotExponent;

    @Option(names = {"-s", "--xy-scale"}, paramLabel = "UNITS_TO_METRES", converter = Converters.XyScale.class,
            description = "Like gdaldem -s: horizontal cell size = CRS units × this (e.g. 111120 for degrees); a "
                    + "finite number above 0. Default: the true metric cell size from the CRS, per row for lat/lon "
                    + "and Web Mercator grids.")
    Double xyScale;

    /** The options record. */
    HillshadeOptions options() {
        HillshadeOptions o = new HillshadeOptions(zFactor, lightMultiple, lightIntensity, darkIntensity,
                spotExponent, Double.NaN);
        return xyScale == null ? o : o.withHorizontalScale(xyScale);
    }
}
