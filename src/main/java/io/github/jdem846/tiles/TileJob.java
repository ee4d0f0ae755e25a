package io.github.jdem846.tiles;

import io.github.jdem846.internal.Interrupts;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.Sun;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.output.InputProtection;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.SunLightField;
import io.github.jdem846.sun.TwilightFade;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * A web-map tile pyramid of one DEM: Web Mercator tiles of 256 × 256 pixels at each zoom of {@code zooms}, every
 * one rendered at its own resolution from the DEM (the reader box-averages the DEM down to about one cell per tile
 * pixel for the zoom, and only the cells under a group of tiles are read), with hillshade slopes and cast shadows
 * measured in ground metres at every latitude, the tint stretched over the whole DEM's range and the cast-shadow
 * halo of each tile read, so colours, light and shadows run on across tiles and zooms. Written as {@code z/x/y.png}
 * files in a directory or as one PMTiles archive ({@link TileFormat}); a tile with no data is not written. Vector
 * overlays ({@link #withOverlays}) are drawn on each tile with data, in tile pixels, continuous across tile seams.
 *
 * <pre>{@code
 * TileReport report = TileJob.of(Path.of("dem.tif"), new ZoomRange(8, 12))
 *         .withScene(Scene.defaults().withShadows(ShadowAlgorithm.SWEEP))
 *         .run(Path.of("relief.pmtiles"), JobListener.NONE);
 * }</pre>
 *
 * <p>Immutable. Interrupting the calling thread stops a run with {@link InterruptedException} and nothing written.
 *
 * @param input            the DEM file, or files read as one grid
 * @param zooms            the zoom levels
 * @param scene            the stages and their settings (its light, tint range and fade are set from {@code sun}
 *                         and the DEM)
 * @param sun              the light: fixed, or the sun at a date and time seen from the DEM's centre (or {@link
 *                         Sun#place()}), the same for every tile; a sun per tile is not allowed
 * @param execution        tiles rendered at once ({@link RenderSettings#parallelism()}) and the renderer's tile
 *                         size; with a shared pool ({@link RenderSettings#withPool}) every tile renders on it. The
 *                         tiles do not depend on them
 * @param pngCompression   deflate level of the tiles, 0 to 9
 * @param overlays         vector overlays drawn on every tile with data, in this order (line widths and radii in
 *                         tile pixels; see {@link io.github.jdem846.overlay.OverlayPainter#onMap})
 */
public record TileJob(DemInput input, ZoomRange zooms, Scene scene, Sun sun, RenderSettings execution,
                      int pngCompression, List<Overlay> overlays) {

    /** Deflate level of the tiles by default: zlib's default, a good size for serving. */
    public static final int DEFAULT_PNG_COMPRESSION = 6;

    /**
     * Checks that the parts are given and that the PNG compression level is 0 to 9.
     *
     * @param input the DEM file, or files read as one grid
     * @param zooms the zoom levels
     * @param scene the stages and their settings (its light, tint range and fade are set from {@code sun} and the DEM)
     * @param sun the light: fixed, or the sun at a date and time seen from the DEM's centre (or {@link Sun#place()}),
     *     the same for every tile; a sun per tile is not allowed
     * @param execution tiles rendered at once ({@link RenderSettings#parallelism()}) and the renderer's tile size; with
     *     a shared pool ({@link RenderSettings#withPool}) every tile renders on it. The tiles do not depend on them
     * @param pngCompression deflate level of the tiles, 0 to 9
     * @param overlays vector overlays drawn on every tile with data, in this order
     */
    public TileJob {
        Objects.requireNonNull(input, "input");
        Objects.requireNonNull(zooms, "zooms");
        Objects.requireNonNull(scene, "scene");
        Objects.requireNonNull(sun, "sun");
        Objects.requireNonNull(execution, "execution");
        if (pngCompression < 0 || pngCompression > 9) {
            throw new IllegalArgumentException("PNG compression level must be 0 to 9, got " + pngCompression);
        }
        overlays = List.copyOf(overlays);
    }

    /**
     * A job without overlays.
     *
     * @param input the DEM file, or files read as one grid
     * @param zooms the zoom levels
     * @param scene the stages and their settings
     * @param sun the light, the same for every tile
     * @param execution tiles rendered at once and the renderer's tile size
     * @param pngCompression deflate level of the tiles, 0 to 9
     */
    public TileJob(DemInput input, ZoomRange zooms, Scene scene, Sun sun, RenderSettings execution,
                   int pngCompression) {
        this(input, zooms, scene, sun, execution, pngCompression, List.of());
    }

    /**
     * Tiles of {@code dem} at {@code zooms} with the original's scene and light, on every processor.
     *
     * @param dem the DEM file
     * @param zooms the zoom levels
     * @return the job
     */
    public static TileJob of(Path dem, ZoomRange zooms) {
        return of(DemInput.of(dem), zooms);
    }

    /**
     * Tiles of {@code dem} (one file or several read as one grid) at {@code zooms}, with the defaults.
     *
     * @param dem the file or files
     * @param zooms the zoom levels
     * @return the job
     */
    public static TileJob of(DemInput dem, ZoomRange zooms) {
        return new TileJob(dem, zooms, Scene.defaults(), Sun.ORIGINAL_DEFAULT, RenderSettings.defaults(),
                DEFAULT_PNG_COMPRESSION);
    }

    /**
     * {@return a copy with other zoom levels}
     *
     * @param value the zoom levels
     */
    public TileJob withZooms(ZoomRange value) {
        return new TileJob(input, value, scene, sun, execution, pngCompression, overlays);
    }

    /**
     * {@return a copy with another scene}
     *
     * @param value the scene
     */
    public TileJob withScene(Scene value) {
        return new TileJob(input, zooms, value, sun, execution, pngCompression, overlays);
    }

    /**
     * {@return a copy with another light}
     *
     * @param value the sun
     */
    public TileJob withSun(Sun value) {
        return new TileJob(input, zooms, scene, value, execution, pngCompression, overlays);
    }

    /**
     * {@return a copy with other threads and renderer tile size}
     *
     * @param value threads and renderer tile size
     */
    public TileJob withExecution(RenderSettings value) {
        return new TileJob(input, zooms, scene, sun, value, pngCompression, overlays);
    }

    /**
     * {@return a copy with another PNG deflate level}
     *
     * @param value the deflate level, 0 to 9
     */
    public TileJob withPngCompression(int value) {
        return new TileJob(input, zooms, scene, sun, execution, value, overlays);
    }

    /**
     * {@return a copy that draws {@code value} on every tile with data}
     *
     * @param value the overlays, drawn in this order
     */
    public TileJob withOverlays(List<Overlay> value) {
        return new TileJob(input, zooms, scene, sun, execution, pngCompression, value);
    }

    /**
     * Renders the pyramid and writes it to {@code output}: a {@code .pmtiles} archive, or else a directory that
     * does not exist yet or is empty. Everything is written to a hidden file or directory beside it first and
     * renamed into place at the end; a failure or an interrupt leaves nothing.
     *
     * @param output the {@code .pmtiles} file or the directory
     * @param listener told of progress ("statistics": rows of the DEM streamed for its range, then "tiles": tiles
     *                 done, of all), notices and the sun computed
     * @return what was written
     * @throws IOException              when the DEM cannot be read or the output not written (naming the file)
     * @throws IllegalArgumentException when the settings do not make sense for map tiles (a sun per tile, a fixed
     *                                  xy-scale, a DEM whose CRS is unknown), saying why
     * @throws InterruptedException     when the calling thread is interrupted
     */
    public TileReport run(Path output, JobListener listener) throws IOException, InterruptedException {
        Objects.requireNonNull(output, "output");
        Objects.requireNonNull(listener, "listener");
        requireTileable();
        TileFormat format = checkOutput(output);
        try {
            TilePlan plan = TilePlan.prepare(this, listener);
            try (TileSink sink = TileSink.open(output)) {
                TileReport report = new PyramidRun(plan, sink, listener).execute(output, format);
                listener.phaseDone("render");
                if (report.written() == 0) {
                    throw new IOException("no tile of zoom " + zooms + " holds data of " + input.first()
                            + ": nothing written");
                }
                sink.commit(plan.tileSetInfo());
                listener.phaseDone("write");
                return report;
            }
        } catch (IOException e) {
            throw Interrupts.interruptedOr(e);
        }
    }

    /**
     * Checks, before any work, that the pyramid can be written to {@code output} ({@link TileSink#open}) and that
     * it is none of the input files.
     *
     * @param output the {@code .pmtiles} file or the directory
     * @return the format {@code output} names
     * @throws io.github.jdem846.output.OutputOverwritesInputException when {@code output} is an input file or its
     *                                  sidecar, however spelt (a symbolic link, a relative path)
     * @throws IOException              naming the output and what is wrong
     * @throws IllegalArgumentException for a format that is not written
     */
    public TileFormat checkOutput(Path output) throws IOException {
        TileFormat format = TileFormat.of(output);
        InputProtection.checkFile(output, DemReader.filesOf(input));
        if (format == TileFormat.PMTILES) {
            PmTilesSink.checkTarget(output);
        } else {
            DirectorySink.checkTarget(output);
        }
        return format;
    }

    /**
     * Checks the settings map tiles cannot honour, before anything is read.
     *
     * @throws IllegalArgumentException for a sun per tile (tiles would not match at their seams) or a fixed
     *                                  xy-scale (tile cells are measured on the ground, row by row)
     */
    public void requireTileable() {
        if (sun.perTile()) {
            throw new IllegalArgumentException("a sun per tile is not used for map tiles: every tile gets the sun "
                    + "seen from the DEM's centre (or the place given), so that light matches across tiles");
        }
        if (!Double.isNaN(scene.hillshadeOptions().horizontalScale())) {
            throw new IllegalArgumentException("a fixed xy-scale does not apply to map tiles: their cells are "
                    + "measured in ground metres row by row");
        }
    }

    /** The scene with the light, the fade, the whole DEM's tint range and the lowest elevation for the sweep. */
    Scene sceneFor(DemInfo info, ElevationStatistics range, JobListener listener) {
        LightDirection direction;
        double fade = 0;
        if (sun.byTime()) {
            SunLightField field = SunLightField.of(info.geometry(), sun.time(), sun.place(), 0, Observer.SEA_LEVEL);
            direction = field.central();
            listener.sun(field.centralSun());
            if (sun.twilight()) {
                fade = TwilightFade.ORIGINAL.darkening(field.centralSun().zenithDegrees());
            }
        } else {
            direction = sun.direction();
        }
        Scene s = scene.withLight(direction).withFade(fade).withTintRange(range);
        return s.hasShadows() ? s.withShadowOptions(s.shadowOptions().withTerrainMinimum(range.min())) : s;
    }
}
