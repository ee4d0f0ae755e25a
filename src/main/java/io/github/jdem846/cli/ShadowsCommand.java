package io.github.jdem846.cli;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.render.DemLoader;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.Clamp;
import io.github.jdem846.shadow.ShadowAlgorithm;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 shadows FILE -o MASK.png|MASK.tif}: the cast-shadow mask, 8-bit, 0 = lit, 255 = in shadow (soft
 * shadows: 0–255 = shadowed fraction), row 0 = north, no-data cells 0.
 */
@Command(name = "shadows", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false,
        description = "Write the ray-traced cast-shadow mask: 0 = lit, 255 = in shadow (soft: shadowed fraction).",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written", "1:an input could not be read or the output not written", "2:bad usage"})
public final class ShadowsCommand implements Callable<Integer> {

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
        ShadowAlgorithm alg = algorithm;
        shadowOptions.noteUnused(alg, err);
        Scene scene = Scene.defaults().withTint(null).withHillshade(null).withShadows(alg)
                .withShadowOptions(shadowOptions.options());
        Scene warmUpScene = scene.withLight(new LightDirection(300, 10));
        KernelWarmUp warmUp = KernelWarmUp.start(dem -> new Renderer(new RenderSettings(1, 64)).shadows(dem,
                warmUpScene, RenderProgress.NONE), input.file());
        DemLoader.Loaded loaded;
        try {
            // besides the grid: the mask, and its bytes
            loaded = input.load(CommandSupport.shadowHalo(sun, input.body(), 1, scene.shadowOptions(), err),
                    input.hasWindow(), Float.BYTES + Byte.BYTES);
        } finally {
            warmUp.stop();
        }
        times.lap("read");
        scene = scene.withShadowOptions(CommandSupport.forLoadedGrid(scene.shadowOptions(), loaded));
        CommandSupport.printNotices(loaded, err);
        SunOptions.Lighting lighting = sun.light(loaded.dem().geometry(), input.body(), execution.tileSize, err);
        float[] mask;
        try (ConsoleProgress progress = ConsoleProgress.create(output.quiet)) {
            mask = new Renderer(execution.settings()).shadows(loaded.dem(), scene.withLight(lighting.field()),
                    loaded.area(), progress);
        }
        times.lap("shadows");
        byte[] bytes = new byte[mask.length];
        for (int i = 0; i < mask.length; i++) {
            bytes[i] = (byte) Math.round(Clamp.between(mask[i], 0f, 1f) * 255f);
        }
        output.writeGray(bytes, CommandSupport.outputGeometry(loaded), null, execution, err);
        times.lap("write");
        times.print(verbose.isVerbose(), err);
        return 0;
    }
}
