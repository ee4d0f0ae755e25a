package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/**
 * {@code jdem846 tint FILE -o OUT.png --tint NAME|FILE}: the hypsometric/bathymetric tint alone (like
 * {@code gdaldem color-relief -alpha}); no-data is transparent.
 */
@Command(name = "tint", mixinStandardHelpOptions = true,
        description = "Write the elevation tint alone (RGBA, no-data transparent), like gdaldem color-relief -alpha.")
public final class TintCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

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
        input.requireConsistent();
        ReliefJob job = input.job(Product.TINT).withScene(Scene.defaults().withTint(tint.ramp()))
                .withExecution(execution.settings());
        return new JobRunner(spec, input, output, execution, verbose).run(job, null);
    }
}
