package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeOptions;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 skyview FILE -o SVF.png|SVF.tif}: the sky-view factor, 8-bit gray, 1 = no sky … 255 = the whole
 * sky (factor = (value − 1)/254), 0 = no-data, row 0 = north.
 */
@Command(name = "skyview", mixinStandardHelpOptions = true,
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
    ProjectionOptions projection;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        input.requireConsistent();
        HillshadeOptions heights;
        try {
            heights = HillshadeOptions.DEFAULTS.withZFactor(zFactor);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.ParameterException(spec.commandLine(), "Invalid value for option '--z-factor': "
                    + e.getMessage());
        }
        Scene scene = Scene.defaults().withTint(null).withHillshade(null).withHillshadeOptions(heights)
                .withAmbient(1).withSkyDirections(directions);
        ReliefJob job = input.job(Product.SKY_VIEW).withScene(scene).withMercatorScale(mapScale.scale())
                .withExecution(execution.settings());
        if (projection.given()) {
            return new ProjectedJobRunner(spec, input, output, execution, verbose, projection).run(job, null);
        }
        projection.requireConsistent(spec);
        return new JobRunner(spec, input, output, execution, verbose).run(job, null);
    }
}
