package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/**
 * {@code jdem846 render [FILE] -o OUT.png}: the main job — hypsometric tint, hillshade and (optionally) ray-traced
 * cast shadows composed into one RGBA picture.
 */
@Command(name = "render", addMethodSubcommands = false, mixinStandardHelpOptions = true,
        description = "Render a shaded-relief picture: tint × hillshade × cast shadows (the article's method).")
public final class RenderCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Mixin
    SceneOptions sceneOptions;

    @Mixin
    MapScaleOption mapScale;

    @Mixin
    SunOptions sun;

    @Mixin
    ExecutionOptions execution;

    @Mixin
    VerboseOption verbose;

    @Mixin
    ProjectionOptions projection;

    @Mixin
    OverlayOptions overlays;

    @Mixin
    DrapeOptions drape;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        input.requireConsistent();
        sun.requireConsistent(input.bodyOptions);
        sceneOptions.noteUnused(spec.commandLine().getErr());
        ReliefJob job = input.job(Product.RELIEF).withScene(drape.apply(sceneOptions.scene())).withSun(sun.sun())
                .withMercatorScale(mapScale.scale())
                .withExecution(execution.settings());
        overlays.requireValidStyles(spec);
        if (projection.given()) {
            return new ProjectedJobRunner(spec, input, output, execution, verbose, projection)
                    .withOverlays(overlays.read()).run(job, sun.time());
        }
        projection.requireConsistent(spec);
        return new JobRunner(spec, input, output, execution, verbose).withOverlays(overlays.read())
                .run(job, sun.time());
    }
}
