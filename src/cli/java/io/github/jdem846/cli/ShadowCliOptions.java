package io.github.jdem846.cli;

import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import java.io.PrintWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code --soft-shadows}, {@code --curvature}, {@code --refraction} and {@code --thin-features}. */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class ShadowCliOptions {

    @Option(names = "--soft-shadows",
            description = "The sun as a 0.53° disk: cells get the shadowed fraction of the disk (penumbrae).")
    boolean soft;

    @Option(names = "--curvature",
            description = "Account for the Earth's curvature and refraction along the rays (matters beyond ~10 km).")
    boolean curvature;

    @Option(names = "--refraction", paramLabel = "K", defaultValue = "0.13", converter = Converters.Refraction.class,
            description = "Refraction coefficient for --curvature, -1 to 1. Default: ${DEFAULT-VALUE}.")
    double refraction;

    @Option(names = "--thin-features",
            description = "sweep: also test each cell's own ray at the steepest terrain of its strip, so that features "
                    + "one or two cells wide (spikes, narrow ridges) cast their whole shadow off the grid axes; "
                    + "1.6-2.5 times the sweep's time. The sweep still spreads such shadows sideways: for lidar "
                    + "surfaces with poles and trees use --shadows exact.")
    boolean thinFeatures;

    /** Says on {@code err} when an option given has no effect with {@code algorithm}. */
    void noteUnused(ShadowAlgorithm algorithm, PrintWriter err) {
        if (thinFeatures && algorithm != ShadowAlgorithm.SWEEP) {
            err.println("jdem846: note: --thin-features changes only the sweep; it has no effect with "
                    + (algorithm == ShadowAlgorithm.NONE ? "no shadows" : MethodNames.of(algorithm)));
        }
    }

    /** The options record (sweep/march defaults otherwise). */
    ShadowOptions options() {
        ShadowOptions o = ShadowOptions.DEFAULTS.withSoftShadows(soft).withThinFeatures(thinFeatures);
        return curvature ? o.withEarthCurvature(true, refraction, Double.NaN) : o;
    }
}
