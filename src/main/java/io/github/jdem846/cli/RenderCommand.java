package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 render [FILE] -o OUT.png}: the main job — hypsometric tint, hillshade and (optionally) ray-traced
 * cast shadows composed into one RGBA picture.
 */
@Command(name = "render", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false,
        description = "Render a shaded-relief picture: tint × hillshade × cast shadows (the article's method).",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written", "1:an input could not be read or the output not written", "2:bad usage"})
public final class RenderCommand implements Callable<Integer> {

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Mixin
    TintOptions tint;

    @Option(names = "--hillshade", paramLabel = "METHOD", defaultValue = "jdem846",
            converter = Converters.HillshadeOrNone.class,
            description = "jdem846 (the article's, default), horn, multidirectional or none.")
    HillshadeMethod method;

    @Mixin
    ShadingOptions shading;

    @Option(names = "--shadows", paramLabel = "ALGORITHM", defaultValue = "none",
            converter = Converters.Algorithm.class,
            description = "Cast shadows: none (default), sweep (fast, O(cells)), march (the article's ray march, "
                    + "fixed) or exact (the slow reference).")
    ShadowAlgorithm algorithm;

    @Option(names = "--shadow-intensity", paramLabel = "0..1", defaultValue = "0.4",
            converter = Converters.ShadowIntensity.class,
            description = "A cell in cast shadow loses 2 × this much brightness, 0 to 1. Default: ${DEFAULT-VALUE}.")
    double shadowIntensity;

    @Mixin
    ShadowCliOptions shadowOptions;

    @Mixin
    SunOptions sun;

    @Mixin
    ExecutionOptions execution;

    @Mixin
    VerboseOption verbose;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        input.requireConsistent();
        sun.requireConsistent(input.bodyOptions);
        shadowOptions.noteUnused(algorithm, spec.commandLine().getErr());
        Scene scene = Scene.defaults().withTint(tint.ramp()).withHillshade(method)
                .withHillshadeOptions(shading.options()).withShadows(algorithm)
                .withShadowOptions(shadowOptions.options()).withShadowIntensity(shadowIntensity);
        ReliefJob job = input.job(Product.RELIEF).withScene(scene).withSun(sun.sun())
                .withExecution(execution.settings());
        return new JobRunner(spec, input, output, execution, verbose).run(job, sun.time());
    }
}
