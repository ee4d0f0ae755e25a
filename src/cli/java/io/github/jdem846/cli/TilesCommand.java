package io.github.jdem846.cli;

import io.github.jdem846.render.Scene;
import io.github.jdem846.tiles.TileFormat;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.TileReport;
import io.github.jdem846.tiles.ZoomRange;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ListResourceBundle;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code jdem846 tiles FILE --zoom 0-12 -o DIR|OUT.pmtiles}: a web-map tile pyramid (Web Mercator, XYZ scheme) of
 * the relief, every zoom rendered from the DEM at its own resolution, with the shading options of {@code render}.
 */
@Command(name = "tiles", addMethodSubcommands = false, mixinStandardHelpOptions = true,
        description = "Render web-map tiles (Web Mercator, z/x/y, 256 × 256 PNG) of the relief for a range of zoom "
                + "levels: a z/x/y.png directory, or one PMTiles archive when OUT ends in .pmtiles.")
public final class TilesCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

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

    @Option(names = "--progress", description = "Show progress even when stderr is not a terminal: a line per "
            + "update, for logs.")
    boolean progress;

    @Mixin
    SceneOptions sceneOptions;

    @Mixin
    OverlayOptions overlays;

    @Mixin
    DrapeOptions drape;

    @Mixin
    SunOptions sun;

    @Mixin
    ExecutionOptions execution;

    @Mixin
    VerboseOption verbose;

    CommandSpec spec;

    /**
     * Picocli hands over the command's spec. Here tiles also gives it the {@link Descriptions} of the options it
     * words its own way, as a bundle instance, so that nothing is looked up by name.
     */
    @CommandLine.Spec
    void spec(CommandSpec value) {
        spec = value;
        value.resourceBundle(new Descriptions());
    }

    /**
     * The tile job the parsed arguments describe, the one {@link #call()} runs: the options checked against each
     * other as for {@code jdem846 tiles}, and the FILE arguments resolved (a directory or a quoted glob to the DEM
     * files in it, as a mosaic). For a program that runs the job itself after
     * {@code new CommandLine(new TilesCommand()).parseArgs(args)}; the tiles go to {@link #output()}.
     *
     * @param err where notes go: an option that has no effect, how many DEM files a directory or glob gave
     * @return the job
     * @throws CommandLine.ParameterException on bad usage, with the message {@code jdem846 tiles} prints: options
     *                                        that do not go together or do not apply to tiles ({@code --xy-scale},
     *                                        {@code --sun-per-tile}), an output that is neither a directory nor a
     *                                        {@code .pmtiles} name, an unknown ramp, a glob that matches no DEM
     * @throws IOException                    when a colour file, an overlay file, a drape image or a directory
     *                                        named cannot be read, or the directory holds no DEM file
     * @throws IllegalArgumentException       when {@code --tint} names a colour file that does not exist
     */
    public TileJob tileJob(PrintWriter err) throws IOException {
        return tileJob(err, files);
    }

    /**
     * {@link #tileJob(PrintWriter)} with its DEM read from {@code inputs} in place of the FILE arguments: for a
     * runner that reads copies of them (the Spark job's executors, which get remote files copied to local disk).
     *
     * @param inputs files, directories or quoted globs, as FILE arguments are
     */
    public TileJob tileJob(PrintWriter err, java.util.List<String> inputs) throws IOException {
        sun.requireConsistent(new BodyOptions());
        sceneOptions.noteUnused(err);
        if (sceneOptions.xyScaleGiven()) {
            throw Usage.error(spec, "--xy-scale does not apply to tiles: their cells are measured in ground metres "
                    + "row by row");
        }
        if (execution.memory != null) {
            throw Usage.error(spec, "--memory does not apply to tiles: they are read and rendered in blocks of "
                    + "at most 4 × 4 tiles, whatever the zoom");
        }
        if (sun.perTile) {
            throw Usage.error(spec, "--sun-per-tile does not apply to tiles: every tile gets the sun seen from the "
                    + "DEM's centre (or --sun-at), so that the light matches across tiles");
        }
        Usage.check(spec, "--output", () -> TileFormat.of(output));
        overlays.requireValidStyles(spec);
        Scene scene = drape.apply(sceneOptions.scene());
        InputPaths.Resolved resolved = InputPaths.resolve(spec, inputs);
        for (String note : resolved.notes()) {
            err.println("jdem846: note: " + note);
        }
        return TileJob.of(resolved.input(), zooms).withScene(scene).withSun(sun.sun())
                .withExecution(execution.settings()).withPngCompression(pngLevel).withOverlays(overlays.read());
    }

    /**
     * The parsed {@code -o}: a directory for z/x/y.png tiles, or a {@code .pmtiles} archive.
     *
     * @return the output path as given
     */
    public Path output() {
        return output;
    }

    /** @return whether {@code -q} asked for no progress bar and no summary line */
    public boolean quiet() {
        return quiet;
    }

    /** @return the FILE arguments as given */
    public java.util.List<String> files() {
        return java.util.List.copyOf(files);
    }

    /** @return the {@code -o} argument as typed: a URI such as {@code hdfs://host/tiles} kept whole */
    public String outputArgument() {
        java.util.List<String> typed = spec.findOption("--output").originalStringValues();
        return typed.isEmpty() ? output.toString() : typed.get(typed.size() - 1);
    }

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        TileJob job = tileJob(err);
        PhaseTimes times = new PhaseTimes();
        TileReport report;
        try (ConsoleProgress bar = ConsoleProgress.create(quiet, progress, err)) {
            report = job.run(output, new ConsoleJobListener(bar, err, times, sun.time()));
        }
        if (!quiet) {
            PrintWriter out = spec.commandLine().getOut();
            out.println(summary(report));
            out.flush();
        }
        times.print(verbose.isVerbose(), err);
        return 0;
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

    /**
     * The descriptions tiles gives options it shares with {@code render} ({@link SceneOptions}): picocli reads an
     * option's description from the command's resource bundle, by its description key, before the option's own.
     */
    private static final class Descriptions extends ListResourceBundle {
        @Override
        protected Object[][] getContents() {
            return new Object[][] {
                {"shadows", "Cast shadows: none (default), sweep, march or exact; each tile reads the terrain toward "
                        + "the sun that can shade it, so shadows run on across tiles."},
            };
        }
    }
}
