package io.github.jdem846.job;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.ImageSink;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.DemTiles;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A picture rendered in tiles (a memory budget far too small for the picture, or tiles forced smaller still) is the
 * same file, byte for byte, as the picture rendered in memory: for every product, on a UTM and a latitude/longitude
 * grid, with a window, a reduced size, the real sun (one for the picture, or one per tile) and cast shadows of a low
 * sun that cross many tiles.
 */
class TiledRenderTest {

    static final Path TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.flt");
    static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.flt");
    static final Path JACKSBORO_TIF = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif");
    static final Path LUXEMBOURG = Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif");
    static final Path VANCOUVER = Path.of("testdata/dem/vancouver-island_topobathy_2min_mercator.flt");
    private static final RenderSettings TWO_THREADS = new RenderSettings(2, 64);
    private static final WriteOptions NO_SIDECARS = WriteOptions.defaults()
            .withSidecars(WriteOptions.Sidecars.NONE);
    private static final ZonedDateTime MORNING = ZonedDateTime.parse("2024-06-21T06:30-07:00[America/Los_Angeles]");

    @TempDir
    Path tmp;

    /** The layout the job chooses for its budget. */
    private static final ReliefJob.LayoutChooser CHOSEN = TileLayout::choose;

    /** Tiles of {@code across × down} units, whatever the budget. */
    private static ReliefJob.LayoutChooser forced(int across, int down) {
        return (plan, halo, unit, needs, budget) -> TileLayout.sized(plan, halo, needs, across * unit, down * unit);
    }

    /**
     * Writes {@code job} in memory and in tiles under {@code budget} bytes, cut by {@code layouts}; asserts that the
     * files are equal and that there were at least {@code minTiles} tiles, a band of rows for each row of them.
     *
     * @return the notices of the tiled run
     */
    private List<String> assertTiledEqualsInMemory(String name, ReliefJob job, long budget,
                                                   ReliefJob.LayoutChooser layouts, int minTiles) throws Exception {
        ReliefJob j = job.withExecution(TWO_THREADS);
        Path memory = tmp.resolve("memory-" + name);
        j.runAndWrite((picture, rgba) -> {
            throw new AssertionError("the picture fits the default budget: no tiles");
        }, result -> result.write(memory, NO_SIDECARS), JobListener.NONE);
        Path tiled = tmp.resolve("tiled-" + name);
        AtomicInteger bands = new AtomicInteger();
        WriteOptions o = job.product() == Product.HILLSHADE ? NO_SIDECARS.withNoData(0) : NO_SIDECARS;
        List<String> notices = new ArrayList<>();
        j.withMemory(budget).runAndWrite((picture, rgba) -> counting(rgba
                ? ImageOutput.openRgba(tiled, picture.width(), picture.height(), GeoReference.of(picture), o)
                : ImageOutput.openGray(tiled, picture.width(), picture.height(), GeoReference.of(picture), o),
                bands), result -> fail("a budget of " + budget + " bytes must not hold the picture"),
                new JobListener() {
                    @Override
                    public void notice(String message) {
                        notices.add(message);
                    }
                }, layouts);
        int[] tiles = tiles(notices);
        assertEquals(tiles[1], bands.get(), name + ": a band of rows for each row of tiles");
        assertTrue(tiles[0] * tiles[1] >= minTiles, name + ": " + notices);
        assertArrayEquals(Files.readAllBytes(memory), Files.readAllBytes(tiled), name);
        return notices;
    }

    /** {columns, rows} of tiles, from the notice that says the picture is rendered in tiles. */
    static int[] tiles(List<String> notices) {
        for (String n : notices) {
            Matcher m = Pattern.compile("rendering it in (\\d+) × (\\d+) tiles").matcher(n);
            if (m.find()) {
                return new int[] {Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2))};
            }
        }
        throw new AssertionError("no notice of tiles in " + notices);
    }

    /** {@code sink}, counting the bands appended to it. */
    static ImageSink counting(ImageSink sink, AtomicInteger bands) {
        return new ImageSink() {
            @Override
            public int width() {
                return sink.width();
            }

            @Override
            public int height() {
                return sink.height();
            }

            @Override
            public int rowsWritten() {
                return sink.rowsWritten();
            }

            @Override
            public void appendRgba(int[] argb, int rows) throws IOException {
                bands.incrementAndGet();
                sink.appendRgba(argb, rows);
            }

            @Override
            public void appendGray(byte[] gray, int rows) throws IOException {
                bands.incrementAndGet();
                sink.appendGray(gray, rows);
            }

            @Override
            public WriteResult commit() throws IOException {
                return sink.commit();
            }

            @Override
            public void close() throws IOException {
                sink.close();
            }
        };
    }

    private static Scene sweep() {
        return Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);
    }

    @Test
    void reliefWithSweepShadowsOfAWholeLatLonFile() throws Exception {
        List<String> notices = assertTiledEqualsInMemory("jacksboro.tif", ReliefJob.of(JACKSBORO)
                .withScene(sweep()).withSun(Sun.fixed(135, 15)), 300_000, CHOSEN, 6);
        assertTrue(notices.get(notices.size() - 1).matches("the 403×344 picture needs \\d+ MiB at once, more than"
                + " the memory budget of 293 KiB: rendering it in 1 × \\d+ tiles of up to 403×\\d+ pixels"),
                notices.toString());
    }

    @Test
    void hillshadeAndTintInBandsAndInColumns() throws Exception {
        assertTiledEqualsInMemory("hs.png", ReliefJob.of(JACKSBORO_TIF).withProduct(Product.HILLSHADE)
                .withScene(Scene.defaults().withHillshade(HillshadeMethod.HORN)), 100_000, CHOSEN, 6);
        assertTiledEqualsInMemory("tint.tif", ReliefJob.of(JACKSBORO).withProduct(Product.TINT), 1, forced(8, 6),
                16);
    }

    @Test
    void shadowMasksOfTheMarchAndOfSoftShadows() throws Exception {
        ReliefJob mask = ReliefJob.of(JACKSBORO).withProduct(Product.SHADOWS).withSun(Sun.fixed(250, 12));
        assertTiledEqualsInMemory("march.png", mask.withScene(Scene.defaults().withShadows(ShadowAlgorithm.MARCH)),
                300_000, CHOSEN, 6);
        assertTiledEqualsInMemory("soft.png", mask.withScene(sweep().withShadowOptions(sweep().shadowOptions()
                .withSoftShadows(true))), 1, forced(8, 6), 16);
    }

    @Test
    void theRealSunOverAReducedWindowOfAUtmGrid() throws Exception {
        ReliefJob j = ReliefJob.of(TUJUNGA).withScene(sweep()).withSun(Sun.at(MORNING))
                .withWindow(Window.cells(100, 50, 900, 500));
        assertTiledEqualsInMemory("reduced.png", j.withSize(OutputSize.scale(0.6)), 1_000_000, CHOSEN, 6);
        // one sun per tile of 64 cells: the picture's tiles start on the same cells whatever the tiling
        assertTiledEqualsInMemory("per-tile.png", j.withSun(j.sun().perTile(true)), 1, forced(3, 2), 12);
    }

    @Test
    void shadowsOfALowSunCrossManyTiles() throws Exception {
        // at 3° the shadows may reach 190 cells west and 80 north: across three columns and two rows of tiles
        ReliefJob low = ReliefJob.of(JACKSBORO).withScene(sweep()).withSun(Sun.fixed(290, 3));
        List<String> notices = assertTiledEqualsInMemory("low.png", low, 700_000, CHOSEN, 4);
        assertTrue(notices.toString().contains("tiles of up to 403×"), "bands: " + notices);
        assertTiledEqualsInMemory("low-columns.png", low.withProduct(Product.SHADOWS), 1, forced(8, 6), 16);
    }

    @Test
    void aWebMercatorGridMeasuredOnTheGroundRendersInTilesAsInMemory() throws Exception {
        // ground cell sizes row by row (MercatorScale.GROUND): the halo toward a low sun, the sweep's lines and the
        // normals of every tile must use the sizes of the whole picture's rows, at full size, enlarged, reduced
        ReliefJob low = ReliefJob.of(VANCOUVER).withScene(sweep()).withSun(Sun.fixed(300, 4));
        List<String> notices = assertTiledEqualsInMemory("vancouver.png", low, 1, forced(2, 2), 9);
        assertTrue(notices.stream().anyMatch(n -> n.startsWith("Web Mercator grid: slopes and shadow lengths use "
                + "the cells' ground size")), notices.toString());
        assertTiledEqualsInMemory("vancouver-x3.png", low.withSize(OutputSize.scale(3)), 1, forced(6, 5), 12);
        assertTiledEqualsInMemory("vancouver-window.png", low.withProduct(Product.SHADOWS)
                .withWindow(Window.cells(10, 20, 90, 60)).withSize(OutputSize.width(70)), 1, forced(1, 1), 9);
        assertTiledEqualsInMemory("vancouver-hs.tif", low.withProduct(Product.HILLSHADE)
                .withScene(Scene.defaults().withHillshade(HillshadeMethod.HORN)), 1, forced(2, 1), 8);
    }

    /**
     * An enlarged picture (7.3 pixels per cell) with no-data outside Luxembourg's border: each tile's grid is
     * interpolated from the cells around it (the halo in cells of the file covers the interpolation's), and its
     * anti-aliased edge and shadows are those of the whole picture; also for a window, whose read halo covers the
     * interpolation too.
     */
    @Test
    void anEnlargedPictureWithNoDataEdgesRendersInTilesAsInMemory() throws Exception {
        ReliefJob lux = ReliefJob.of(LUXEMBOURG).withScene(sweep()).withSun(Sun.fixed(135, 20))
                .withSize(OutputSize.width(700));
        assertTiledEqualsInMemory("lux-x7.png", lux, 1, forced(3, 2), 16);
        assertTiledEqualsInMemory("lux-x7-hs.png", lux.withProduct(Product.HILLSHADE), 1, forced(4, 3), 16);
        assertTiledEqualsInMemory("lux-x7-window.png", lux.withWindow(Window.cells(50, 30, 40, 40))
                .withSize(OutputSize.scale(7.3)), 1, forced(2, 2), 9);
    }

    @Test
    void aMosaicOfFourFilesRendersInTilesAsInMemory() throws Exception {
        Dem whole = DemReader.read(JACKSBORO);
        List<Path> quarters = DemTiles.gridFloat(whole, DemTiles.quarters(403, 344, 200, 170, 1),
                Files.createDirectories(tmp.resolve("quarters")), "q", DemTiles.sibling(JACKSBORO, "prj"));
        assertTiledEqualsInMemory("mosaic.png", ReliefJob.of(DemInput.of(quarters)).withScene(sweep())
                .withSun(Sun.fixed(135, 6)), 1, forced(8, 6), 16);
    }

    @Test
    void skyLightAndTheSkyViewFactorWithASearchRadiusRenderInTilesAsInMemory() throws Exception {
        // the halo follows the radius (2 km: 68 cells of 30 m), so every tile sees every horizon the picture sees
        Scene sky = sweep().withLightModel(io.github.jdem846.render.LightModel.SKY).withAmbient(0.35)
                .withSkyDirections(16).withSkyRadius(2000);
        ReliefJob tujunga = ReliefJob.of(TUJUNGA).withScene(sky).withSun(Sun.at(MORNING))
                .withWindow(Window.cells(300, 100, 500, 360));
        assertTiledEqualsInMemory("sky.png", tujunga, 1, forced(3, 2), 6);
        assertTiledEqualsInMemory("sky-view.png", tujunga.withProduct(Product.SKY_VIEW), 1, forced(4, 3), 12);
        // a lat/lon grid: the halo counts cells of the smallest ground size
        assertTiledEqualsInMemory("sky-latlon.png", ReliefJob.of(JACKSBORO).withScene(sky.withSkyRadius(1500))
                .withSun(Sun.fixed(135, 15)), 1, forced(3, 3), 9);
    }

    @Test
    void progressCountsThePicturesPixelsAcrossTiles() throws Exception {
        List<long[]> updates = new ArrayList<>();
        ReliefJob.of(JACKSBORO).withProduct(Product.HILLSHADE).withExecution(TWO_THREADS).withMemory(100_000)
                .runAndWrite(tmp.resolve("p.png"), NO_SIDECARS, new JobListener() {
                    @Override
                    public synchronized void update(String stage, long done, long total) {
                        assertEquals("hillshade", stage);
                        updates.add(new long[] {done, total});
                    }
                });
        assertTrue(updates.size() > 10, updates.size() + " updates");
        for (int i = 0; i < updates.size(); i++) {
            assertEquals(403L * 344, updates.get(i)[1]);
            assertTrue(i == 0 || updates.get(i)[0] > updates.get(i - 1)[0], "progress only grows");
        }
        assertEquals(403L * 344, updates.get(updates.size() - 1)[0]);
    }

    @Test
    void anInterruptedTiledRunLeavesNoFile() throws IOException {
        Path out = tmp.resolve("interrupted").resolve("relief.png");
        Files.createDirectories(out.getParent());
        Thread caller = Thread.currentThread();
        AtomicInteger tilesDone = new AtomicInteger();
        ReliefJob job = ReliefJob.of(JACKSBORO).withScene(sweep()).withExecution(TWO_THREADS).withMemory(300_000);
        assertThrows(InterruptedException.class, () -> job.runAndWrite(out, NO_SIDECARS, new JobListener() {
            @Override
            public void update(String stage, long done, long total) {
                if (done >= 403L * 64 && tilesDone.getAndIncrement() == 0) {
                    caller.interrupt();                  // after a band or two have gone to the file
                }
            }
        }));
        assertTrue(!Thread.interrupted(), "the interrupt status is cleared, as InterruptedException says");
        try (Stream<Path> left = Files.list(out.getParent())) {
            assertEquals(List.of(), left.toList(), "nothing written, nothing staged left behind");
        }
    }

    @Test
    void aTileThatCannotFitIsRefusedWithWhatItNeeds() {
        ReliefJob low = ReliefJob.of(TUJUNGA).withProduct(Product.SHADOWS).withScene(sweep())
                .withSun(Sun.fixed(290, 3)).withMemory(500_000);
        Path out = tmp.resolve("refused.png");
        InsufficientHeapException e = assertThrows(InsufficientHeapException.class,
                () -> low.runAndWrite(out, NO_SIDECARS, JobListener.NONE));
        assertTrue(e.getMessage().matches("even the smallest tile, 16×16 pixels, with the halo read around it \\(1190,"
                + " 435, 2 and 2 cells west, north, east and south: the cast shadows' reach toward the sun, the file's"
                + " relief / tan\\(sun elevation\\)\\) needs \\d+ (KiB|MiB), more than the memory budget of 489 KiB:"
                + " give a larger budget .*a higher sun.*"), e.getMessage());
        assertTrue(e.givesAdvice());
        assertTrue(Files.notExists(out));
    }
}
