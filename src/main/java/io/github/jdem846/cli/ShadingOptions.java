package io.github.jdem846.cli;

import io.github.jdem846.shade.HillshadeOptions;
import picocli.CommandLine.Option;

/** The hillshade knobs with the original's defaults: z-factor, light multiple, intensities, spot exponent. */
public final class ShadingOptions {

    @Option(names = {"-z", "--z-factor"}, paramLabel = "FACTOR", defaultValue = "1",
            description = "Vertical exaggeration. Default: ${DEFAULT-VALUE}.")
    double zFactor;

    @Option(names = "--light-multiple", paramLabel = "FACTOR", defaultValue = "0.75",
            description = "jdem846 method: heights are scaled by this for the normals only. Default: ${DEFAULT-VALUE}.")
    double lightMultiple;

    @Option(names = "--light-intensity", paramLabel = "0..1", defaultValue = "0.75",
            description = "Relative light intensity (scales lit slopes). Default: ${DEFAULT-VALUE}.")
    double lightIntensity;

    @Option(names = "--dark-intensity", paramLabel = "0..1", defaultValue = "1.0",
            description = "Relative dark intensity (scales shaded slopes). Default: ${DEFAULT-VALUE}.")
    double darkIntensity;

    @Option(names = "--spot-exponent", paramLabel = "EXP", defaultValue = "1",
            description = "Sign-preserving exponent on the brightness. Default: ${DEFAULT-VALUE}.")
    double spotExponent;

    @Option(names = {"-s", "--xy-scale"}, paramLabel = "UNITS_TO_METRES",
            description = "Like gdaldem -s: horizontal cell size = CRS units × this (e.g. 111120 for degrees). "
                    + "Default: the true metric cell size from the CRS, per row for lat/lon grids.")
    Double xyScale;

    /** The options record. */
    HillshadeOptions options() {
        HillshadeOptions o = new HillshadeOptions(zFactor, lightMultiple, lightIntensity, darkIntensity,
                spotExponent, Double.NaN);
        return xyScale == null ? o : o.withHorizontalScale(xyScale);
    }
}
