package io.github.jdem846.cli;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.render.DemLoader;
import io.github.jdem846.render.RenderProgress;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Renderer;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 hillshade FILE -o OUT.png|OUT.tif}: a single-band gray hillshade, 1..255 with 0 = no-data, like
 * {@code gdaldem hillshade -compute_edges} (horn and multidirectional give gdaldem's bytes).
 */
@Command(name = "hillshade", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false,
        description = "Write a gray hillshade (0 = no-data, 1..255), gdaldem-compatible for horn/multidirectional.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written", "1:an input could not be read or the output not written", "2:bad usage"})
public final class HillshadeCommand implements Callable<Integer> {

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Option(names = {"--method", "--alg"}, paramLabel = "METHOD", defaultValue = "jdem846",
            converter = Converters.Method.class,
            description = "jdem846 (the article's, default), horn (gdaldem's default) or multidirectional.")
    HillshadeMethod method;

    @Option(names = "--multidirectional", description = "Same as --method multidirectional (gdaldem's flag).")
    boolean multidirectional;

    @Mixin
    ShadingOptions shading;

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
        HillshadeMethod m = multidirectional ? HillshadeMethod.MULTIDIRECTIONAL : method;
        HillshadeOptions options = shading.options();
        KernelWarmUp warmUp = KernelWarmUp.start(dem -> new Renderer(new RenderSettings(1, 64)).hillshadeGray(dem, m,
                options, LightField.uniform(new LightDirection(315, 45)), RenderProgress.NONE), input.file());
        DemLoader.Loaded loaded;
        try {
            loaded = input.load(DemLoader.Halo.uniform(1), false, Byte.BYTES);
        } finally {
            warmUp.stop();
        }
        times.lap("read");
        CommandSupport.printNotices(loaded, err);
        SunOptions.Lighting lighting = sun.light(loaded.dem().geometry(), input.body(), execution.tileSize, err);
        byte[] gray;
        try (ConsoleProgress progress = ConsoleProgress.create(output.quiet)) {
            gray = new Renderer(execution.settings()).hillshadeGray(loaded.dem(), m, options, lighting.field(),
                    loaded.area(), progress);
        }
        times.lap("hillshade");
        output.writeGray(gray, CommandSupport.outputGeometry(loaded), 0.0, execution, err);
        times.lap("write");
        times.print(verbose.isVerbose(), err);
        return 0;
    }
}
