package io.github.jdem846.cli;

import io.github.jdem846.job.Product;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.raster.GridRequestException;
import io.github.jdem846.view.Camera;
import io.github.jdem846.view.LookAt;
import io.github.jdem846.view.ViewJob;
import io.github.jdem846.view.ViewOptions;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/**
 * {@code jdem846 view [FILE] -o OUT.png}: the shaded relief of {@code render} draped on the terrain and seen in
 * perspective ({@link ViewJob}); {@code --width}/{@code --height} are the picture's size.
 */
@Command(name = "view", addMethodSubcommands = false, mixinStandardHelpOptions = true,
        description = {"Render a 3-D perspective view: the shaded relief (tint × hillshade × cast shadows) draped on "
                + "the terrain, seen by a camera at an azimuth and elevation, optionally on the body's globe.",
            "--width and --height give the picture's size (default 1200 × 800)."},
        footer = {"", "Examples:",
            "  jdem846 view dem.tif -o view.png --camera-azimuth 200 --camera-elevation 35 --exaggeration 2",
            "  jdem846 view dem.tif -o globe.png --globe --distance 3000000 --exaggeration 20",
            "  jdem846 view dem.tif -o valley.png --camera-position 382479,3796143,560 --look-at 384729,3796203"})
public final class ViewCommand implements Callable<Integer> {

    @Mixin
    WritingCommandAttributes attributes;

    @Mixin
    InputOptions input;

    @Mixin
    OutputOptions output;

    @Option(names = "--camera-azimuth", paramLabel = "DEG", defaultValue = "200",
            description = "Where the camera stands, degrees clockwise from north as seen from the terrain's centre "
                    + "(default: ${DEFAULT-VALUE}, south-south-west, looking north-north-east).")
    double cameraAzimuth;

    @Option(names = "--camera-elevation", paramLabel = "DEG", defaultValue = "35",
            description = "The camera's angle above the horizon, above 0 and at most 90 (90: straight down). "
                    + "Default: ${DEFAULT-VALUE}.")
    double cameraElevation;

    @Option(names = "--distance", paramLabel = "M",
            description = "The camera's distance from the terrain's centre in metres (default: the terrain fills "
                    + "the picture).")
    Double distance;

    @Option(names = "--camera-position", paramLabel = "X,Y,Z", converter = PointValue.class,
            description = "Where the camera stands, in the DEM's CRS units (as --window takes them) and its height "
                    + "in the DEM's units, exaggerated like the terrain; with --look-at, instead of --camera-azimuth, "
                    + "--camera-elevation and --distance.")
    Point cameraPosition;

    @Option(names = "--look-at", paramLabel = "X,Y[,Z]", converter = PointValue.class,
            description = "The point at the picture's centre, in the DEM's CRS units; without Z, on the terrain "
                    + "there. Needs --camera-position.")
    Point lookAt;

    @Option(names = "--fov", paramLabel = "DEG", defaultValue = "40",
            description = "Vertical field of view in degrees, above 0 and below 180. Default: ${DEFAULT-VALUE}.")
    double fov;

    @Option(names = "--exaggeration", paramLabel = "FACTOR", defaultValue = "1",
            description = "Vertical exaggeration of the terrain (not of the hillshade: see --z-factor), above 0 and "
                    + "at most 1000. Default: ${DEFAULT-VALUE}.")
    double exaggeration;

    @Option(names = "--globe",
            description = "Place the terrain on the body's ellipsoid at its latitudes and longitudes and draw the "
                    + "rest of the body, on black space; use --distance to step back.")
    boolean globe;

    @Option(names = "--no-base",
            description = "No walls from the terrain's edges down to a base below it (drawn by default, not on the "
                    + "globe).")
    boolean noBase;

    @Mixin
    OverlayOptions overlays;

    @Mixin
    SceneOptions sceneOptions;

    @Mixin
    DrapeOptions drape;

    @Mixin
    SunOptions sun;

    @Mixin
    ExecutionOptions execution;

    @Mixin
    VerboseOption verbose;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /** The picture's default size. */
    static final int DEFAULT_WIDTH = 1200;
    static final int DEFAULT_HEIGHT = 800;

    @Override
    public Integer call() throws Exception {
        if (input.scale != null) {
            throw Usage.error(spec, "view takes the picture's size as --width and --height, not --scale");
        }
        if (output.worldFile || output.cog) {
            throw Usage.error(spec, "a perspective view has no place on the ground: --world-file and --cog do not"
                    + " apply");
        }
        sun.requireConsistent(input.bodyOptions);
        sceneOptions.noteUnused(spec.commandLine().getErr());
        overlays.requireValidStyles(spec);
        Camera camera = camera();
        ViewOptions options;
        try {
            options = ViewOptions.defaults().withGlobe(globe).withBase(!noBase).withExaggeration(exaggeration);
        } catch (IllegalArgumentException e) {
            throw Usage.invalid(spec, e.getMessage(), "--exaggeration");
        }
        Usage.check(spec, "--output", () -> io.github.jdem846.output.ImageOutput.filesWritten(output.path(),
                WriteOptions.defaults()));
        ReliefJob relief = ReliefJob.of(input.input() != null ? input.input() : BundledSample.extract())
                .withProduct(Product.RELIEF)
                .withWindow(input.window).withBody(input.body()).withScene(drape.apply(sceneOptions.scene()))
                .withSun(sun.sun()).withExecution(execution.settings()).withMemory(execution.memory());
        PrintWriter err = spec.commandLine().getErr();
        PhaseTimes times = new PhaseTimes();
        WriteOptions writeOptions = output.writeOptions(execution);
        try (ConsoleProgress progress = ConsoleProgress.create(output.quiet, output.progress, err)) {
            new ViewJob(relief, camera, options, overlays.read()).runAndWrite(output.path(), writeOptions,
                    new ConsoleJobListener(progress, err, times, sun.time()));
        } catch (GridRequestException e) {
            throw input.usageError(e);
        }
        times.print(verbose.isVerbose(), err);
        return 0;
    }

    /** The camera's position and look-at point, checked against the options placing it by direction. */
    private LookAt lookAt() {
        if (cameraPosition == null || lookAt == null) {
            throw Usage.error(spec, cameraPosition == null ? "--look-at needs --camera-position X,Y,Z"
                    : "--camera-position needs --look-at X,Y[,Z] (the point the camera looks at)");
        }
        for (String option : new String[] {"--camera-azimuth", "--camera-elevation", "--distance"}) {
            if (spec.commandLine().getParseResult().hasMatchedOption(option)) {
                throw Usage.error(spec, option + " does not apply with --camera-position and --look-at: the camera"
                        + " is placed by its position");
            }
        }
        if (cameraPosition.length() != 3) {
            throw Usage.invalid(spec, "a position needs three numbers, X,Y,Z (the height too), got "
                    + cameraPosition.length(),
                    "--camera-position");
        }
        double targetZ = lookAt.length() == 3 ? lookAt.v()[2] : Double.NaN;
        if (cameraPosition.v()[0] == lookAt.v()[0] && cameraPosition.v()[1] == lookAt.v()[1] && cameraPosition.v()[2] == targetZ) {
            throw Usage.error(spec, "--look-at is the camera's own position: look at another point");
        }
        return new LookAt(cameraPosition.v()[0], cameraPosition.v()[1], cameraPosition.v()[2], lookAt.v()[0], lookAt.v()[1], targetZ);
    }

    /** A point given as {@code X,Y} or {@code X,Y,Z}. */
    record Point(double[] v) {
        int length() {
            return v.length;
        }
    }

    /** {@code X,Y} or {@code X,Y,Z}: two or three finite numbers. */
    static final class PointValue implements ITypeConverter<Point> {
        @Override
        public Point convert(String text) {
            String[] parts = text.split(",", -1);
            String expected = "'" + text + "' is not a point: expected X,Y or X,Y,Z, finite numbers in the DEM's "
                    + "CRS units and height units";
            if (parts.length < 2 || parts.length > 3) {
                throw new TypeConversionException(expected);
            }
            double[] v = new double[parts.length];
            for (int i = 0; i < parts.length; i++) {
                try {
                    v[i] = Double.parseDouble(parts[i].trim());
                } catch (NumberFormatException e) {
                    throw new TypeConversionException(expected);
                }
                if (!Double.isFinite(v[i])) {
                    throw new TypeConversionException(expected);
                }
            }
            return new Point(v);
        }
    }

    /** The camera of the options. */
    private Camera camera() {
        int w = input.width != null ? input.width
                : input.height != null ? Math.max(1, input.height * DEFAULT_WIDTH / DEFAULT_HEIGHT) : DEFAULT_WIDTH;
        int h = input.height != null ? input.height : Math.max(1, w * DEFAULT_HEIGHT / DEFAULT_WIDTH);
        Camera base = Camera.defaults();
        Camera[] camera = {base};
        Usage.check(spec, "--camera-azimuth", () -> camera[0] = camera[0].withDirection(cameraAzimuth, 35));
        Usage.check(spec, "--camera-elevation", () -> camera[0] = camera[0].withDirection(cameraAzimuth,
                cameraElevation));
        Usage.check(spec, "--distance", () -> camera[0] = camera[0].withDistance(distance != null ? distance : 0));
        Usage.check(spec, "--fov", () -> camera[0] = camera[0].withFieldOfView(fov));
        if (cameraPosition != null || lookAt != null) {
            camera[0] = camera[0].withLookAt(lookAt());
        }
        String[] size = input.width != null && input.height != null ? new String[] {"--width", "--height"}
                : new String[] {input.height != null ? "--height" : "--width"};
        try {
            return camera[0].withSize(w, h);
        } catch (IllegalArgumentException e) {
            throw Usage.invalid(spec, e.getMessage(), size);
        }
    }
}
