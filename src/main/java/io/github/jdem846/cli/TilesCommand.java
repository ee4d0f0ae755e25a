package io.github.jdem846.cli;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.sun.SunPosition;
import io.github.jdem846.tiles.TileFormat;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.TileReport;
import io.github.jdem846.tiles.ZoomRange;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code jdem846 tiles FILE --zoom 0-12 -o DIR|OUT.pmtiles}: a web-map tile pyramid (Web Mercator, XYZ scheme) of
 * the relief, every zoom rendered from the DEM at its own resolution, with the shading options of {@code render}.
 */
@Command(name = "tiles", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false,
        description = "Render web-map tiles (Web Mercator, z/x/y, 256 × 256 PNG) of the relief for a range of zoom "
                + "levels: a z/x/y.png directory, or one PMTiles archive when OUT ends in .pmtiles.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:written", "1:an input could not be read or the output not written", "2:bad usage"})
public final class TilesCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "FILE",
            description = "GeoTIFF, GridFloat (.flt), ESRI ASCII (.asc), BIL (.bil) or SRTM .hgt with a known CRS; "
                    + "several files, a directory or a quoted glob are read as one grid (a mosaic).")
    java.util.List<String> files;

    @Option(names = {"-Z", "--zoom"}, required = true, paramLabel = "MIN-MAX", converter = ZoomConverter.class,
            description = "Zoom levels, e.g. 0-12 or 10: 0 to 22.")
    ZoomRange zooms;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT",
            description = "A new or empty directory for z/x/y.png tiles, or an archive name ending in .pmtiles. "
                    + "Written beside it under a hidden name first and renamed at the end, so a failure leaves "
                    + "nothing behind.")
    Path output;

    @Option(names = "--png-level", paramLabel = "0..9", defaultValue = "" + TileJob.DEFAULT_PNG_COMPRESSION,
            converter = PngLevelConverter.class,
            description = "Deflate level of the tiles, 0 (none) to 9 (smallest). Default: ${DEFAULT-VALUE}.")
    int pngLevel;

    @Option(names = {"-q", "--quiet"}, description = "No progress bar and no summary line.")
    boolean quiet;

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
            description = "Cast shadows: none (default), sweep, march or exact; each tile reads the terrain toward "
                    + "the sun that can shade it, so shadows run on across tiles.")
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
        TileJob job = tileJob(err, files);
        PhaseTimes times = new PhaseTimes();
        TileReport report;
        try (ConsoleProgress progress = ConsoleProgress.create(quiet)) {
            report = job.run(output, new JobListener() {
                @Override
                public void update(String stage, long done, long total) {
                    progress.update(stage, done, total);
                }

                @Override
                public void notice(String message) {
                    err.println("jdem846: note: " + message);
                    err.flush();
                }

                @Override
                public void phaseDone(String phase) {
                    times.lap(phase);
                }

                @Override
                public void sun(SunPosition p) {
                    err.println(String.format(Locale.ROOT, "jdem846: sun at %s: azimuth %.2f°, elevation %.2f°%s",
                            sun.time(), p.azimuthDegrees(), p.elevationDegrees(),
                            p.isBelowHorizon() ? " (below the horizon: no direct light)" : ""));
                    err.flush();
                }
            });
        }
        if (!quiet) {
            PrintWriter out = spec.commandLine().getOut();
            out.println(summary(report));
            out.flush();
        }
        times.print(verbose.isVerbose(), err);
        return 0;
    }

    /**
     * The job these parsed arguments describe, with its DEM read from {@code inputs} (the FILE arguments as given,
     * or their local copies): checked as {@code call} checks them; notes on the inputs go to {@code err}. For
     * another runner of the same arguments (the Spark job) after {@code new CommandLine(command).parseArgs(args)}.
     *
     * @throws CommandLine.ParameterException for options that do not go together or inputs that name no DEM
     * @throws java.io.IOException              when a directory of inputs cannot be listed
     */
    public TileJob tileJob(PrintWriter err, java.util.List<String> inputs) throws java.io.IOException {
        sun.requireConsistent(new BodyOptions());
        shadowOptions.noteUnused(algorithm, err);
        if (shading.xyScale != null) {
            throw Usage.error(spec, "--xy-scale does not apply to tiles: their cells are measured in ground metres "
                    + "row by row");
        }
        if (sun.perTile) {
            throw Usage.error(spec, "--sun-per-tile does not apply to tiles: every tile gets the sun seen from the "
                    + "DEM's centre (or --sun-at), so that the light matches across tiles");
        }
        Usage.check(spec, "--output", () -> TileFormat.of(output));
        Scene scene = Scene.defaults().withTint(tint.ramp()).withHillshade(method)
                .withHillshadeOptions(shading.options()).withShadows(algorithm)
                .withShadowOptions(shadowOptions.options()).withShadowIntensity(shadowIntensity);
        InputPaths.Resolved resolved = InputPaths.resolve(spec, inputs);
        for (String note : resolved.notes()) {
            err.println("jdem846: note: " + note);
        }
        err.flush();
        return TileJob.of(resolved.input(), zooms).withScene(scene).withSun(sun.sun())
                .withExecution(execution.settings()).withPngCompression(pngLevel);
    }

    /** @return the FILE arguments as given */
    public java.util.List<String> files() {
        return java.util.List.copyOf(files);
    }

    /** @return the {@code -o} argument as typed (a URI such as {@code hdfs://…} kept whole) */
    public String outputArgument() {
        java.util.List<String> typed = spec.findOption("--output").originalStringValues();
        return typed.isEmpty() ? output.toString() : typed.get(typed.size() - 1);
    }

    /** "wrote 85 tiles of zoom 8-12 to OUT (3 empty tiles left out)" with one clause per zoom. */
    static String summary(TileReport report) {
        StringBuilder s = new StringBuilder(String.format(Locale.ROOT, "wrote %d tiles (%.1f MB of PNG) to %s",
                report.written(), report.bytes() / 1e6, report.output()));
        if (report.empty() > 0) {
            s.append(String.format(Locale.ROOT, "; %d tiles without data left out", report.empty()));
        }
        for (TileReport.Zoom z : report.zooms()) {
            s.append(String.format(Locale.ROOT, "%n  zoom %2d: %d tiles written of %d", z.z(), z.written(),
                    z.range().count()));
        }
        return s.toString();
    }

    /** Parses {@code --zoom}. */
    static final class ZoomConverter implements CommandLine.ITypeConverter<ZoomRange> {
        @Override
        public ZoomRange convert(String value) {
            try {
                return ZoomRange.parse(value);
            } catch (IllegalArgumentException e) {
                throw new CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    /** Parses {@code --png-level}. */
    static final class PngLevelConverter implements CommandLine.ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            try {
                int level = Integer.parseInt(value.strip());
                if (level >= 0 && level <= 9) {
                    return level;
                }
            } catch (NumberFormatException e) {
                // below
            }
            throw new CommandLine.TypeConversionException("'" + value + "' is not a deflate level 0 to 9");
        }
    }
}
