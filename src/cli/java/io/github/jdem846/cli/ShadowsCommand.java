package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 shadows FILE -o MASK.png|MASK.tif}: the cast-shadow mask, 8-bit, 0 = lit, 255 = in shadow (soft
 * shadows: 0–255 = shadowed fraction), row 0 = north, no-data cells 0.
 */
@Command(name = "shadows", addMethodSubcommands = false, mixinStandardHelpOptions = true,
        description = "Write the ray-traced cast-shadow mask: 0 = lit, 255 = in shadow (soft: shadowed fraction).")
public final class ShadowsCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Option(names = {"--algorithm", "--shadows"}, paramLabel = "ALGORITHM", defaultValue = "sweep",
            converter = Converters.MaskAlgorithm.class,
            description = "sweep (default, O(cells)), march (the article's ray march, fixed) or exact (reference).")
    ShadowAlgorithm algorithm;

    @Mixin
    ShadowCliOptions shadowOptions;

    @Mixin
    MapScaleOption mapScale;

    @Mixin
    SunOptions sun;

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
        sun.requireConsistent(input.bodyOptions);
        shadowOptions.noteUnused(algorithm, spec.commandLine().getErr());
        Scene scene = Scene.defaults().withShadows(algorithm).withShadowOptions(shadowOptions.options());
        ReliefJob job = input.job(Product.SHADOWS).withScene(scene).withSun(sun.sun())
                .withMercatorScale(mapScale.scale())
                .withExecution(execution.settings());
        if (projection.given()) {
            return new ProjectedJobRunner(spec, input, output, execution, verbose, projection).run(job, sun.time());
        }
        projection.requireConsistent(spec);
        return new JobRunner(spec, input, output, execution, verbose).run(job, sun.time());
    }
}
