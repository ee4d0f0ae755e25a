package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 tint FILE... -o OUT.png --tint NAME|FILE}, or gdaldem color-relief's order
 * {@code jdem846 tint IN COLORFILE OUT}: the hypsometric/bathymetric tint alone (like
 * {@code gdaldem color-relief -alpha}); no-data is transparent.
 */
@Command(name = "tint", addMethodSubcommands = false, mixinStandardHelpOptions = true, modelTransformer = GdaldemPositionals.Transformer.class,
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

    @Option(names = "-alpha", description = "Accepted for gdaldem's habit and ignored: the tint always has an alpha "
            + "band (no-data transparent).")
    boolean alpha;

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
        GdaldemPositionals.Split split = GdaldemPositionals.split(spec, input.files(), output.path(), true);
        input.useFiles(split.inputs());
        output.use(split.output());
        if (split.ramp() != null) {
            tint.usePositional(split.ramp());
        }
        input.requireConsistent();
        ReliefJob job = input.job(Product.TINT).withScene(Scene.defaults().withTint(tint.ramp()))
                .withExecution(execution.settings());
        if (projection.given()) {
            return new ProjectedJobRunner(spec, input, output, execution, verbose, projection).run(job, null);
        }
        projection.requireConsistent(spec);
        return new JobRunner(spec, input, output, execution, verbose).run(job, null);
    }
}
