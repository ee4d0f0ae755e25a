package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.SkyViewOptions;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 skyview FILE -o SVF.png|SVF.tif}: the sky-view factor, 8-bit gray, 1 = no sky … 255 = the whole
 * sky (factor = (value − 1)/254), 0 = no-data, row 0 = north; with {@code --float} the factor itself as a float32
 * GeoTIFF, NaN = no-data.
 */
@Command(name = "skyview", addMethodSubcommands = false, mixinStandardHelpOptions = true,
        description = "Write the sky-view factor (the share of the sky each cell sees, from its horizons): 8-bit "
                + "gray, 1 = none … 255 = the whole sky, 0 = no-data.")
public final class SkyViewCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Option(names = {"--directions", "--sky-directions"}, paramLabel = "D", defaultValue = "32",
            converter = Converters.SkyDirections.class,
            description = "Azimuths whose horizons are averaged, 4 to 360. Default: ${DEFAULT-VALUE}.")
    int directions;

    @Option(names = "--sky-radius", paramLabel = "METRES", converter = Converters.SkyRadius.class,
            description = "Search horizons within this many metres of each cell (terrain farther away does not "
                    + "count), as WhiteboxTools' and RVT's maximum search distance. Default: the whole grid.")
    Double radius;

    @Option(names = "--float",
            description = "Write the factor itself, 0 to 1, as a float32 GeoTIFF (no-data NaN, declared) instead of "
                    + "8-bit gray; the output must be .tif/.tiff. Held in memory whole (no tiles).")
    boolean floatValues;

    @Option(names = {"--z-factor", "-z"}, paramLabel = "Z", defaultValue = "1",
            description = "Vertical exaggeration of the heights. Default: ${DEFAULT-VALUE}.")
    double zFactor;

    @Mixin
    MapScaleOption mapScale;

    @Mixin
    ExecutionOptions execution;

    @Mixin
    VerboseOption verbose;

    @Mixin
    GrayOverlayRefusal overlay;

    @Mixin
    ProjectionOptions projection;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        input.requireConsistent();
        if (floatValues && output.path() != null && !ReliefJob.isGeoTiff(output.path())) {
            throw new CommandLine.ParameterException(spec.commandLine(), "Invalid value for option '--output': "
                    + "--float writes a float32 GeoTIFF: name a .tif or .tiff file, not '" + output.path() + "'");
        }
        HillshadeOptions heights;
        try {
            heights = HillshadeOptions.DEFAULTS.withZFactor(zFactor);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), "Invalid value for option '--z-factor': "
                    + e.getMessage());
        }
        Scene scene = Scene.defaults().withTint(null).withHillshade(null).withHillshadeOptions(heights)
                .withAmbient(1).withSkyDirections(directions)
                .withSkyRadius(radius != null ? radius : SkyViewOptions.UNBOUNDED);
        ReliefJob job = input.job(Product.SKY_VIEW).withScene(scene).withMercatorScale(mapScale.scale())
                .withExecution(execution.settings());
        if (projection.given()) {
            if (floatValues) {
                throw new CommandLine.ParameterException(spec.commandLine(), "Invalid value for option "
                        + "'--projection': --float values are written on the DEM's own grid only; leave out --float to "
                        + "project the 8-bit factor");
            }
            return new ProjectedJobRunner(spec, input, output, execution, verbose, projection).run(job, null);
        }
        projection.requireConsistent(spec);
        return new JobRunner(spec, input, output, execution, verbose).withValues(floatValues).run(job, null);
    }
}
