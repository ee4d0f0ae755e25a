package io.github.jdem846.cli;

import io.github.jdem846.io.Window;
import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.raster.GridRequestException;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.io.DemInput;
import java.io.IOException;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * The DEM to draw and which part of it at what size: {@code [FILE...] --window --width --height --scale}. Without
 * FILE the bundled sample DEM is used; several files, a directory or a glob pattern are read as one grid
 * ({@link InputPaths}).
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class InputOptions {

    @Parameters(arity = "0..*", paramLabel = "FILE",
            description = "GeoTIFF, GridFloat (.flt), ESRI ASCII (.asc), BIL (.bil), SRTM .hgt or a GDAL .vrt; the "
                    + "bundled sample DEM (Big Tujunga, California) when omitted. Several files, a directory (its "
                    + "DEM files) or a quoted glob such as 'tiles/*.hgt' are read as one grid, a mosaic: one CRS, "
                    + "one cell size, one grid; gaps are no-data, overlapping cells the mean of the files.")
    List<String> files;

    private InputPaths.Resolved resolved;

    @Mixin
    BodyOptions bodyOptions;

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    @Option(names = "--window", paramLabel = "W,S,E,N|cells:COL,ROW,W,H", converter = Converters.WindowValue.class,
            description = "Render only this part: a box in the DEM's CRS units (west,south,east,north; west < east, "
                    + "south < north; clipped to the grid) or a cell rectangle 'cells:col,row,width,height' (row 0 = "
                    + "north; inside the grid). Only the window and the halo the stages need are read.")
    Window window;

    @Option(names = "--width", paramLabel = "PIXELS", converter = Converters.Width.class,
            description = "Output width, 1 to " + OutputSize.MAX_SIDE + " (height follows the aspect ratio unless "
                    + "--height is given too; at most " + OutputSize.MAX_PIXELS + " pixels in all).")
    Integer width;

    @Option(names = "--height", paramLabel = "PIXELS", converter = Converters.Height.class,
            description = "Output height, 1 to " + OutputSize.MAX_SIDE + ".")
    Integer height;

    @Option(names = "--scale", paramLabel = "FACTOR", converter = Converters.Scale.class,
            description = "Output pixels per DEM cell, e.g. 0.25 for a quarter-size picture: above 0, at most "
                    + OutputSize.MAX_SIDE + ", and enough for one pixel on each side.")
    Double scale;

    /** The output size these options ask for. */
    OutputSize size() {
        if (scale != null) {
            if (width != null || height != null) {
                throw Usage.error(command, "give either --scale or --width/--height, not both");
            }
            return OutputSize.scale(scale);
        }
        if (width != null && height != null) {
            try {
                return new OutputSize(width, height, 0);
            } catch (IllegalArgumentException e) {
                throw Usage.invalid(command, e.getMessage(), "--width", "--height");
            }
        }
        if (width != null) {
            return OutputSize.width(width);
        }
        return height != null ? OutputSize.height(height) : OutputSize.FULL;
    }

    /**
     * Refuses options that do not go together (a scale with a width or height, --body with --radius) before
     * anything is read.
     *
     * @throws picocli.CommandLine.ParameterException naming the options
     */
    void requireConsistent() {
        size();
        body();
    }

    /** True when {@code --window} was given. */
    boolean hasWindow() {
        return window != null;
    }

    /**
     * A job for {@code product} of the DEM named (or the bundled sample), with the window, size and body of these
     * options.
     */
    ReliefJob job(Product product) throws IOException {
        DemInput in = input();
        return ReliefJob.of(in != null ? in : BundledSample.extract()).withProduct(product).withWindow(window)
                .withSize(size()).withBody(body());
    }

    /** A window or a size that does not fit the grid, found once its header was read, as bad usage. */
    CommandLine.ParameterException usageError(GridRequestException e) {
        return e.part() == GridRequestException.Part.WINDOW ? Usage.invalid(command, e.getMessage(), "--window")
                : Usage.invalid(command, e.getMessage(), sizeOptions());
    }

    /** The size options given, for a message. */
    private String[] sizeOptions() {
        return scale != null ? new String[] {"--scale"} : width != null && height != null
                ? new String[] {"--width", "--height"} : new String[] {width != null ? "--width" : "--height"};
    }

    /** The body of {@code --body}/{@code --radius}; the Earth by default. */
    io.github.jdem846.sun.Body body() {
        return bodyOptions.body();
    }

    /** What stderr says when no FILE is given. */
    static final String SAMPLE_NOTE = "no FILE given: rendering the bundled sample, Big Tujunga, California (SRTM 30 m,"
            + " 600 × 400 cells)";

    /** The FILE arguments as given (empty for none). */
    List<String> files() {
        return files == null ? List.of() : List.copyOf(files);
    }

    /**
     * Reads {@code inputs} in place of the FILE arguments, for a command whose last FILE arguments are something
     * else ({@link GdaldemPositionals}). Before {@link #input()} is first called.
     */
    void useFiles(List<String> inputs) {
        if (resolved != null) {
            throw new IllegalStateException("the FILE arguments are already resolved");
        }
        files = List.copyOf(inputs);
    }

    /**
     * The DEM file or files named (directories and glob patterns resolved, once; how they were found is said on
     * stderr, and that the bundled sample is drawn when none is named), or {@code null} for the sample.
     */
    DemInput input() throws IOException {
        if (resolved == null) {
            resolved = InputPaths.resolve(command, files);
            java.io.PrintWriter err = command.commandLine().getErr();
            if (resolved.input() == null) {
                err.println("jdem846: note: " + SAMPLE_NOTE);
            }
            for (String note : resolved.notes()) {
                err.println("jdem846: note: " + note);
            }
            err.flush();
        }
        return resolved.input();
    }
}
