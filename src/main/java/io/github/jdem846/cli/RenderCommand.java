package io.github.jdem846.cli;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.render.DemLoader;
import io.github.jdem846.render.RenderedImage;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.io.PrintWriter;
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
        PrintWriter err = spec.commandLine().getErr();
        output.refuseOverwriting(input);
        PhaseTimes times = new PhaseTimes();
        input.requireConsistent();
        sun.requireConsistent(input.bodyOptions);
        shadowOptions.noteUnused(algorithm, err);
        Scene scene = Scene.defaults().withTint(tint.ramp()).withHillshade(method)
                .withHillshadeOptions(shading.options()).withShadows(algorithm)
                .withShadowOptions(shadowOptions.options()).withShadowIntensity(shadowIntensity);
        DemLoader.Halo halo = method == null ? DemLoader.Halo.NONE : DemLoader.Halo.uniform(1);
        if (scene.hasShadows()) {
            halo = halo.union(CommandSupport.shadowHalo(sun, input.body(), scene.hillshadeOptions().zFactor(),
                    scene.shadowOptions(), err));
        }
        Scene warmUpScene = scene.withLight(new LightDirection(320, 25));
        KernelWarmUp warmUp = KernelWarmUp.start(dem -> new Renderer(new RenderSettings(1, 64)).render(dem,
                warmUpScene), input.file());
        DemLoader.Loaded loaded;
        try {
            // besides the grid: the ARGB picture, and the shadow mask
            loaded = input.load(halo, scene.tint() != null || scene.hasShadows() && input.hasWindow(),
                    Integer.BYTES + (scene.hasShadows() ? Float.BYTES : 0));
        } finally {
            warmUp.stop();
        }
        if (scene.hasShadows()) {
            scene = scene.withShadowOptions(CommandSupport.forLoadedGrid(scene.shadowOptions(), loaded));
        }
        times.lap("read");
        CommandSupport.printNotices(loaded, err);
        SunOptions.Lighting lighting = sun.light(loaded.dem().geometry(), input.body(), execution.tileSize, err);
        scene = scene.withLight(lighting.field()).withFade(lighting.fade()).withTintRange(loaded.fileStatistics());
        RenderedImage image;
        try (ConsoleProgress progress = ConsoleProgress.create(output.quiet)) {
            image = new Renderer(execution.settings()).render(loaded.dem(), scene, loaded.area(), progress);
        }
        times.lap("render");
        output.writeRgba(image.argb(), CommandSupport.outputGeometry(loaded), execution, err);
        times.lap("write");
        times.print(verbose.isVerbose(), err);
        return 0;
    }
}
