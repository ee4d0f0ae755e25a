package io.github.jdem846.cli;

import io.github.jdem846.sun.Body;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code --body earth|moon|mars} or {@code --radius M}: the body a DEM lies on, used when its CRS names no ellipsoid
 * (or none was read from the file), for metric cell sizes of geographic grids and the radius of {@code --curvature}.
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
final class BodyOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    @Option(names = "--body", paramLabel = "BODY", converter = Converters.BodyName.class,
            description = "The body the DEM lies on when its CRS names no ellipsoid: earth (default, WGS 84), moon "
                    + "or mars. A sun by date and time is computed for the Earth only.")
    Body named;

    @Option(names = "--radius", paramLabel = "M", converter = Converters.Radius.class,
            description = "Instead of --body: the radius in metres of a spherical body (a finite number above 0).")
    Body sphere;

    /** The body asked for; the Earth when neither option is given. */
    Body body() {
        if (named != null && sphere != null) {
            throw Usage.error(command, "give either --body or --radius, not both");
        }
        return sphere != null ? sphere : named != null ? named : Body.EARTH;
    }

    /**
     * The body, for a sun placed by date and time: the Earth only.
     *
     * @throws picocli.CommandLine.ParameterException for another body
     */
    Body bodyForSunByTime() {
        Body body = body();
        Usage.check(command, sphere != null ? "--radius" : "--body", body::requireSunByDateAndTime);
        return body;
    }

    /** True when the user chose a body. */
    boolean given() {
        return named != null || sphere != null;
    }
}
