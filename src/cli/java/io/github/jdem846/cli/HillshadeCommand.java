package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 hillshade FILE... -o OUT.png|OUT.tif}, or gdaldem's {@code jdem846 hillshade IN OUT}: a single-band
 * gray hillshade, 1..255 with 0 = no-data, like {@code gdaldem hillshade -compute_edges} (horn, multidirectional,
 * combined and igor give gdaldem's bytes). gdaldem's own spellings are accepted: {@code -az}, {@code -alt},
 * {@code -z}, {@code -s}, {@code -multidirectional}, {@code -combined}, {@code -igor} and {@code -compute_edges}.
 */
@Command(name = "hillshade", addMethodSubcommands = false, mixinStandardHelpOptions = true, modelTransformer = GdaldemPositionals.Transformer.class,
        description = "Write a gray hillshade (0 = no-data, 1..255), gdaldem-compatible for horn, multidirectional, "
                + "combined and igor.")
public final class HillshadeCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Option(names = {"--method", "--alg"}, paramLabel = "METHOD", defaultValue = "jdem846",
            converter = Converters.Method.class,
            description = "jdem846 (the article's, default), horn (gdaldem's default), multidirectional, combined "
                    + "(horn darkened by the slope) or igor (slope and aspect only, no sun elevation).")
    HillshadeMethod method;

    @Option(names = {"--multidirectional", "-multidirectional"},
            description = "Same as --method multidirectional (gdaldem's flag).")
    boolean multidirectional;

    @Option(names = {"--combined", "-combined"}, description = "Same as --method combined (gdaldem's flag).")
    boolean combined;

    @Option(names = {"--igor", "-igor"}, description = "Same as --method igor (gdaldem's flag).")
    boolean igor;

    @Option(names = "-compute_edges",
            description = "Accepted for gdaldem's habit and ignored: edges are always computed, as gdaldem does "
                    + "with it.")
    boolean computeEdges;

    @Mixin
    ShadingOptions shading;

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
        GdaldemPositionals.Split split = GdaldemPositionals.split(spec, input.files(), output.path(), false);
        input.useFiles(split.inputs());
        output.use(split.output());
        input.requireConsistent();
        sun.requireConsistent(input.bodyOptions);
        HillshadeMethod chosen = method();
        if (chosen == HillshadeMethod.IGOR && sun.elevation != null) {
            spec.commandLine().getErr().println("jdem846: note: igor uses only the sun's azimuth; --sun-elevation "
                    + "has no effect");
        }
        Scene scene = Scene.defaults().withHillshade(chosen).withHillshadeOptions(shading.options());
        ReliefJob job = input.job(Product.HILLSHADE).withScene(scene).withSun(sun.sun())
                .withMercatorScale(mapScale.scale())
                .withExecution(execution.settings());
        if (projection.given()) {
            return new ProjectedJobRunner(spec, input, output, execution, verbose, projection).run(job, sun.time());
        }
        projection.requireConsistent(spec);
        return new JobRunner(spec, input, output, execution, verbose).run(job, sun.time());
    }

    /**
     * The method of {@code --method} or of one of gdaldem's flags.
     *
     * @throws CommandLine.ParameterException for two flags, or a flag and a different {@code --method}
     */
    private HillshadeMethod method() {
        List<HillshadeMethod> flags = new ArrayList<>();
        if (multidirectional) {
            flags.add(HillshadeMethod.MULTIDIRECTIONAL);
        }
        if (combined) {
            flags.add(HillshadeMethod.COMBINED);
        }
        if (igor) {
            flags.add(HillshadeMethod.IGOR);
        }
        if (flags.isEmpty()) {
            return method;
        }
        List<String> names = flags.stream().map(m -> "--" + MethodNames.of(m)).toList();
        if (flags.size() > 1) {
            throw Usage.error(spec, String.join(" and ", names) + " choose different methods; give one");
        }
        if (spec.commandLine().getParseResult().hasMatchedOption("--method") && method != flags.get(0)) {
            throw Usage.error(spec, "--method " + MethodNames.of(method) + " and " + names.get(0)
                    + " choose different methods; give one");
        }
        return flags.get(0);
    }
}
