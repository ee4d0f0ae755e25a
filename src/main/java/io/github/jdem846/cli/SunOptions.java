package io.github.jdem846.cli;

import io.github.jdem846.light.LightDirection;
import picocli.CommandLine.Option;

/** {@code --sun-azimuth} and {@code --sun-elevation} (the original's defaults 320° and 25°). */
public final class SunOptions {

    @Option(names = {"--sun-azimuth", "--azimuth"}, paramLabel = "DEG", defaultValue = "320",
            description = "Sun azimuth, degrees clockwise from north (any value; reduced to [0, 360)). "
                    + "Default: ${DEFAULT-VALUE}.")
    double azimuth;

    @Option(names = {"--sun-elevation", "--altitude"}, paramLabel = "DEG", defaultValue = "25",
            description = "Sun elevation above the horizon in degrees, -90..90. Default: ${DEFAULT-VALUE}.")
    double elevation;

    /** The light these options describe. */
    LightDirection light() {
        return new LightDirection(azimuth, elevation);
    }
}
