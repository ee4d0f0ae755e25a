package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 hillshade FILE -o OUT.png|OUT.tif}: a single-band gray hillshade, 1..255 with 0 = no-data, like
 * {@code gdaldem hillshade -compute_edges} (horn and multidirectional give gdaldem's bytes).
 */
@Command(name = "hillshade", mixinStandardHelpOptions = true,
        description = "Write a gray hillshade (0 = no-data, 1..255), gdaldem-compatible for horn/multidirectional.")
public final class HillshadeCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

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
        input.requireConsistent();
        sun.requireConsistent(input.bodyOptions);
        Scene scene = Scene.defaults().withHillshade(multidirectional ? HillshadeMethod.MULTIDIRECTIONAL : method)
                .withHillshadeOptions(shading.options());
        ReliefJob job = input.job(Product.HILLSHADE).withScene(scene).withSun(sun.sun())
                .withExecution(execution.settings());
        return new JobRunner(spec, input, output, execution, verbose).run(job, sun.time());
    }
}
