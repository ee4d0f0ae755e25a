package io.github.jdem846.cli;

import io.github.jdem846.sun.Body;
import picocli.CommandLine.Option;

/**
 * {@code --body earth|moon|mars} or {@code --radius M}: the body a DEM lies on, used when its CRS names no ellipsoid
 * (or none was read from the file), for metric cell sizes of geographic grids and the radius of {@code --curvature}.
 */
final class BodyOptions {

    @Option(names = "--body", paramLabel = "BODY",
            description = "The body the DEM lies on when its CRS names no ellipsoid: earth (default, WGS 84), moon "
                    + "or mars. Sun positions from --sun-time are for the Earth only.")
    String bodyName;

    @Option(names = "--radius", paramLabel = "M",
            description = "Instead of --body: the radius in metres of a spherical body.")
    Double radius;

    /** The body asked for; the Earth when neither option is given. */
    Body body() {
        if (bodyName != null && radius != null) {
            throw new IllegalArgumentException("give either --body or --radius, not both");
        }
        if (radius != null) {
            return Body.sphere(radius);
        }
        return bodyName == null ? Body.EARTH : Body.named(bodyName);
    }

    /** True when the user chose a body. */
    boolean given() {
        return bodyName != null || radius != null;
    }
}
