package io.github.jdem846.cli;

import io.github.jdem846.render.DemLoader;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderedImage;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.render.Scene;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/**
 * {@code jdem846 tint FILE -o OUT.png --tint NAME|FILE}: the hypsometric/bathymetric tint alone (like
 * {@code gdaldem color-relief -alpha}); no-data is transparent.
 */
@Command(name = "tint", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false,
        description = "Write the elevation tint alone (RGBA, no-data transparent), like gdaldem color-relief -alpha.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written", "1:an input could not be read or the output not written", "2:bad usage"})
public final class TintCommand implements Callable<Integer> {

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Mixin
    TintOptions tint;

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
        Scene scene = Scene.defaults().withTint(tint.ramp()).withHillshade(null);
        KernelWarmUp warmUp = KernelWarmUp.start(dem -> new Renderer(new RenderSettings(1, 64)).render(dem, scene),
                input.file());
        DemLoader.Loaded loaded;
        try {
            loaded = input.load(DemLoader.Halo.NONE, scene.tint() != null, Integer.BYTES);
        } finally {
            warmUp.stop();
        }
        times.lap("read");
        CommandSupport.printNotices(loaded, err);
        RenderedImage image = new Renderer(execution.settings()).render(loaded.dem(),
                scene.withTintRange(loaded.fileStatistics()), loaded.area(), RenderProgress.NONE);
        times.lap("tint");
        output.writeRgba(image.argb(), CommandSupport.outputGeometry(loaded), execution, err);
        times.lap("write");
        times.print(verbose.isVerbose(), err);
        return 0;
    }
}
