package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.Sun;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.testing.TestDems;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A small pyramid (zoom 8 to 11) of the Jacksboro SRTM 3″ DEM (WGS 84, 403 × 344 cells, 84.414° to 84.078° W,
 * 36.446° to 36.733° N by gdalinfo): which tiles are written, where the data lies in them, that tiles continue across
 * their seams (shadows included), the PMTiles archive read back by a reader written here from the spec, and the
 * tiles against GDAL's ({@code gdal2tiles.py --xyz} of a {@code gdaldem hillshade} of the same DEM: the same tiles,
 * with data in the same pixels but for a pixel's width along the DEM's outline; skipped when GDAL is not installed),
 * and the archive read by protomaps' own Python reader (skipped when the {@code pmtiles} package is not installed).
 */
class TileJobTest {

    static final Path DEM = TestDems.DEM_DIR.resolve(TestDems.JACKSBORO + ".tif");
    // gdalinfo testdata/dem/jacksboro_srtm3s_wgs84.tif: origin and pixel size
    static final double WEST = -84.41375;
    static final double NORTH = 36.732916666666668;
    static final double EAST = WEST + 403 * 0.000833333333333;
    static final double SOUTH = NORTH - 344 * 0.000833333333333;
    static final ZoomRange ZOOMS = new ZoomRange(8, 11);
    /** Cast shadows from a low western sun, so that they cross tile seams. */
    static final Scene SCENE = Scene.defaults().withShadows(ShadowAlgorithm.SWEEP);
    static final Sun SUN = Sun.fixed(280, 8);

    @TempDir
    static Path dir;
    static Path tiles;
    static TileReport report;

    @BeforeAll
    static void render() throws Exception {
        tiles = dir.resolve("tiles");
        report = job().run(tiles, JobListener.NONE);
    }

    static TileJob job() {
        return TileJob.of(DEM, ZOOMS).withScene(SCENE).withSun(SUN).withExecution(new RenderSettings(2, 256))
                .withPngCompression(1);
    }

    /** The wiki's formulas, independent of the code under test. */
    static double column(double lon, int z) {
        return (lon + 180) / 360 * (1 << z) * 256;
    }

    static double row(double lat, int z) {
        double r = Math.toRadians(lat);
        return (1 - Math.log(Math.tan(r) + 1 / Math.cos(r)) / Math.PI) / 2 * (1 << z) * 256;
    }

    static BufferedImage tile(int z, int x, int y) throws IOException {
        return ImageIO.read(tiles.resolve(z + "/" + x + "/" + y + ".png").toFile());
    }

    @Test
    void writesTheTilesThatOverlapTheDem() throws IOException {
        Set<String> expected = new HashSet<>();
        for (int z = ZOOMS.min(); z <= ZOOMS.max(); z++) {
            for (int x = (int) (column(WEST, z) / 256); x <= (int) (column(EAST, z) / 256); x++) {
                for (int y = (int) (row(NORTH, z) / 256); y <= (int) (row(SOUTH, z) / 256); y++) {
                    expected.add(z + "/" + x + "/" + y + ".png");
                }
            }
        }
        Set<String> written;
        try (Stream<Path> files = Files.walk(tiles)) {
            written = files.filter(Files::isRegularFile).map(p -> tiles.relativize(p).toString().replace('\\', '/'))
                    .collect(Collectors.toSet());
        }
        assertEquals(expected, written);
        assertEquals(expected.size(), report.written());
        assertEquals(0, report.empty());
        for (String f : written) {
            BufferedImage img = ImageIO.read(tiles.resolve(f).toFile());
            assertEquals(256, img.getWidth(), f);
            assertEquals(256, img.getHeight(), f);
        }
        try (Stream<Path> siblings = Files.list(dir)) {
            assertEquals(List.of(), siblings.filter(p -> p.getFileName().toString().contains(StagingDirectory.MARK))
                    .collect(Collectors.toList()), "no staging directory is left");
        }
    }

    @Test
    void dataLiesWhereTheDemLies() throws IOException {
        for (int z = ZOOMS.min(); z <= ZOOMS.max(); z++) {
            // the DEM's centre is opaque in its tile
            double cx = column((WEST + EAST) / 2, z);
            double cy = row((NORTH + SOUTH) / 2, z);
            BufferedImage centre = tile(z, (int) cx / 256, (int) cy / 256);
            assertEquals(255, centre.getRGB((int) cx % 256, (int) cy % 256) >>> 24, "centre at zoom " + z);
            // the west and south edges of the data are where the DEM's edges are, within a pixel
            double wx = column(WEST, z);
            double sy = row(SOUTH, z);
            int yMid = (int) cy;
            int xMid = (int) cx;
            assertEdge(z, (int) Math.floor(wx) - 1, yMid, 0);
            assertEdge(z, (int) Math.floor(wx) + 1, yMid, 255);
            assertEdge(z, xMid, (int) Math.floor(sy) + 1, 0);
            assertEdge(z, xMid, (int) Math.floor(sy) - 1, 255);
        }
    }

    private static void assertEdge(int z, int gx, int gy, int alpha) throws IOException {
        BufferedImage t = tile(z, gx / 256, gy / 256);
        assertEquals(alpha, t.getRGB(gx % 256, gy % 256) >>> 24, "alpha at global pixel " + gx + ", " + gy
                + " of zoom " + z);
    }

    @Test
    void tilesContinueAcrossTheirSeams() throws Exception {
        // the 2 × 2 tiles 544..545 × 799..800 of zoom 11 rendered as one 512 × 512 grid, cut in four
        int z = 11;
        DemInput input = DemInput.of(DEM);
        DemInfo info = DemReader.inspect(input).withDefaultEllipsoid(Ellipsoid.WGS84);
        ElevationStatistics range = DemReader.statistics(input);
        Scene scene = job().sceneFor(info, range, JobListener.NONE);
        SourceProjection projection = SourceProjection.of(info.geometry(), info.source());
        ZoomGrid grid = new ZoomGrid(z);
        TileRasterizer rasterizer = new TileRasterizer(grid, scene, range, new RenderSettings(1, 64));
        CellWindow block = new CellWindow(544 * 256, 799 * 256, 512, 512);
        CellWindow need = rasterizer.need(block);
        assertTrue(need.col() < block.col() - 10, "a western sun needs terrain west of the block: " + need);
        int[] whole = rasterizer.render(block, need, new ZoomSource(input, projection, grid).read(need));
        int shadowed = 0;
        int differing = 0;
        int maxDiff = 0;
        for (int ty = 0; ty < 2; ty++) {
            for (int tx = 0; tx < 2; tx++) {
                BufferedImage t = tile(z, 544 + tx, 799 + ty);
                for (int r = 0; r < 256; r++) {
                    for (int c = 0; c < 256; c++) {
                        int a = whole[(ty * 256 + r) * 512 + tx * 256 + c];
                        int b = t.getRGB(c, r);
                        int d = channelDifference(a, b);
                        maxDiff = Math.max(maxDiff, d);
                        differing += d > 0 ? 1 : 0;
                    }
                }
            }
        }
        for (int v : whole) {
            shadowed += (v >>> 24) != 0 && brightness(v) < 90 ? 1 : 0;
        }
        assertTrue(shadowed > 2000, "the low sun casts shadows in the block: " + shadowed + " dark pixels");
        assertEquals(0, maxDiff, differing + " pixels differ between the tiles and the block rendered whole");
    }

    private static int brightness(int argb) {
        return ((argb >> 16 & 255) + (argb >> 8 & 255) + (argb & 255)) / 3;
    }

    private static int channelDifference(int a, int b) {
        int d = 0;
        for (int shift = 0; shift < 32; shift += 8) {
            d = Math.max(d, Math.abs((a >>> shift & 255) - (b >>> shift & 255)));
        }
        return d;
    }

    @Test
    void aSharedPoolWritesTheSameArchive() throws Exception {
        Path own = dir.resolve("own.pmtiles");
        Path shared = dir.resolve("shared.pmtiles");
        job().run(own, JobListener.NONE);
        java.util.concurrent.ForkJoinPool pool = new java.util.concurrent.ForkJoinPool(2);
        try {
            job().withExecution(new RenderSettings(2, 256).withPool(pool)).run(shared, JobListener.NONE);
            assertFalse(pool.isShutdown(), "the caller's pool is left open");
        } finally {
            pool.shutdownNow();
        }
        assertArrayEquals(Files.readAllBytes(own), Files.readAllBytes(shared));
    }

    @Test
    void pmtilesArchiveHoldsTheSameTiles() throws Exception {
        Path archive = dir.resolve("relief.pmtiles");
        TileReport r = job().run(archive, JobListener.NONE);
        assertEquals(report.written(), r.written());
        byte[] file = Files.readAllBytes(archive);
        ByteBuffer h = ByteBuffer.wrap(file, 0, 127).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals("PMTiles", new String(file, 0, 7, java.nio.charset.StandardCharsets.US_ASCII));
        assertEquals(3, file[7]);
        long rootOffset = h.getLong(8);
        long rootLength = h.getLong(16);
        long leafLength = h.getLong(48);
        long dataOffset = h.getLong(56);
        long dataLength = h.getLong(64);
        long addressed = h.getLong(72);
        assertEquals(127, rootOffset);
        assertTrue(127 + rootLength <= 16384, "the root directory lies in the first 16 KiB");
        assertEquals(0, leafLength, "a small archive needs no leaf directories");
        assertEquals(file.length, dataOffset + dataLength);
        assertEquals(report.written(), addressed);
        assertEquals(1, file[96], "clustered");
        assertEquals(2, file[97], "gzip directories");
        assertEquals(1, file[98], "tiles stored as they are");
        assertEquals(2, file[99], "PNG");
        assertEquals(ZOOMS.min(), file[100]);
        assertEquals(ZOOMS.max(), file[101]);
        assertEquals(Math.round(WEST * 1e7), h.getInt(102), 2);
        assertEquals(Math.round(SOUTH * 1e7), h.getInt(106), 2);

        List<long[]> entries = readDirectory(gunzip(file, (int) rootOffset, (int) rootLength));
        long tilesAddressed = entries.stream().mapToLong(e -> e[3]).sum();
        assertEquals(report.written(), tilesAddressed);
        long previousId = -1;
        for (long[] e : entries) {
            assertTrue(e[0] > previousId, "entries ascend by tile ID");
            previousId = e[0] + e[3] - 1;
            for (long k = 0; k < e[3]; k++) {
                int[] zxy = zxy(e[0] + k);
                byte[] png = Files.readAllBytes(tiles.resolve(zxy[0] + "/" + zxy[1] + "/" + zxy[2] + ".png"));
                byte[] stored = java.util.Arrays.copyOfRange(file, (int) (dataOffset + e[1]),
                        (int) (dataOffset + e[1] + e[2]));
                assertArrayEquals(png, stored, "tile " + zxy[0] + "/" + zxy[1] + "/" + zxy[2]);
            }
        }
    }

    @Test
    void protomapsPythonReaderReadsTheArchive() throws Exception {
        assumeTrue(onPath("python3") && runs("python3", "-c", "import pmtiles.reader"),
                "the pmtiles Python package (protomaps/PMTiles) is not installed");
        Path archive = dir.resolve("python.pmtiles");
        job().withZooms(new ZoomRange(10, 11)).run(archive, JobListener.NONE);
        String script = String.join("\n",
                "import sys",
                "from pmtiles.reader import Reader, MmapSource, all_tiles",
                "with open(sys.argv[1], 'rb') as f:",
                "    r = Reader(MmapSource(f))",
                "    h = r.header()",
                "    for (z, x, y), data in all_tiles(r.get_bytes):",
                "        with open(sys.argv[2] + '/%d/%d/%d.png' % (z, x, y), 'rb') as png:",
                "            assert png.read() == data, (z, x, y)",
                "        print(z, x, y)",
                "    print('zooms', h['min_zoom'], h['max_zoom'], r.metadata()['format'])");
        Process p = new ProcessBuilder("python3", "-c", script, archive.toString(), tiles.toString())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        long expected = report.zooms().stream().filter(z -> z.z() >= 10).mapToLong(TileReport.Zoom::written).sum();
        assertEquals(expected, out.lines().filter(l -> l.matches("\\d+ \\d+ \\d+")).count(), out);
        assertTrue(out.contains("zooms 10 11 png"), out);
    }

    private static boolean runs(String... command) {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    static byte[] gunzip(byte[] file, int offset, int length) throws IOException {
        try (InputStream in = new GZIPInputStream(new ByteArrayInputStream(file, offset, length))) {
            return in.readAllBytes();
        }
    }

    /** Decodes a directory (spec 4.3): entries {tileId, offset, length, runLength}. */
    static List<long[]> readDirectory(byte[] d) {
        int[] pos = {0};
        int n = (int) varint(d, pos);
        List<long[]> e = new ArrayList<>();
        long id = 0;
        for (int i = 0; i < n; i++) {
            id += varint(d, pos);
            e.add(new long[] {id, 0, 0, 0});
        }
        for (int i = 0; i < n; i++) {
            e.get(i)[3] = varint(d, pos);
        }
        for (int i = 0; i < n; i++) {
            e.get(i)[2] = varint(d, pos);
        }
        for (int i = 0; i < n; i++) {
            long v = varint(d, pos);
            e.get(i)[1] = v == 0 && i > 0 ? e.get(i - 1)[1] + e.get(i - 1)[2] : v - 1;
        }
        assertEquals(d.length, pos[0], "the directory ends with its last offset");
        return e;
    }

    static long varint(byte[] d, int[] pos) {
        long v = 0;
        for (int shift = 0; ; shift += 7) {
            int b = d[pos[0]++] & 0xFF;
            v |= (long) (b & 0x7F) << shift;
            if (b < 0x80) {
                return v;
            }
        }
    }

    /** The spec reference's tileid_to_zxy (the Python package of protomaps/PMTiles). */
    static int[] zxy(long id) {
        int z = 0;
        while (((1L << (2 * (z + 1))) - 1) / 3 <= id) {
            z++;
        }
        long pos = id - ((1L << (2 * z)) - 1) / 3;
        long x = 0;
        long y = 0;
        for (long s = 1; s < (1L << z); s <<= 1) {
            long rx = (pos / 2) & s;
            long ry = (pos ^ rx) & s;
            if (ry == 0) {
                if (rx != 0) {
                    x = s - 1 - x;
                    y = s - 1 - y;
                }
                long t = x;
                x = y;
                y = t;
            }
            x += rx;
            y += ry;
            pos >>= 1;
        }
        return new int[] {z, (int) x, (int) y};
    }

    @Test
    void anInterruptedRunLeavesNothing() throws IOException {
        Path empty = Files.createDirectories(dir.resolve("interrupted"));
        for (String name : new String[] {"out", "out.pmtiles"}) {
            JobListener interrupting = new JobListener() {
                @Override
                public void update(String stage, long done, long total) {
                    if (done == 0) {
                        Thread.currentThread().interrupt();
                    }
                }
            };
            assertThrows(InterruptedException.class, () -> job().run(empty.resolve(name), interrupting));
            assertTrue(!Thread.interrupted(), "the interrupt is reported by the exception, not left set");
            try (Stream<Path> left = Files.list(empty)) {
                assertEquals(List.of(), left.collect(Collectors.toList()), name);
            }
        }
    }

    @Test
    void refusesOutputsItCannotWrite() throws IOException {
        Path full = Files.createDirectories(dir.resolve("full"));
        Files.writeString(full.resolve("keep.txt"), "mine");
        IOException e = assertThrows(IOException.class, () -> job().run(full, JobListener.NONE));
        assertTrue(e.getMessage().contains("not empty"), e.getMessage());
        assertEquals(List.of(full.resolve("keep.txt")), Files.list(full).collect(Collectors.toList()));
        assertThrows(IllegalArgumentException.class, () -> job().run(dir.resolve("x.mbtiles"), JobListener.NONE));
        assertThrows(IllegalArgumentException.class, () -> job().withSun(Sun.at(
                java.time.ZonedDateTime.parse("2024-06-21T12:00Z")).perTile(true)).run(dir.resolve("y"),
                JobListener.NONE));
        assertThrows(IllegalArgumentException.class, () -> job().withScene(SCENE.withHillshadeOptions(
                SCENE.hillshadeOptions().withHorizontalScale(111120))).run(dir.resolve("z"), JobListener.NONE));
    }

    @Test
    void sameTilesAndSameFootprintAsGdal2tiles() throws Exception {
        assumeTrue(onPath("gdaldem") && onPath("gdal2tiles.py"), "gdaldem and gdal2tiles.py are not installed");
        Path work = Files.createDirectories(dir.resolve("gdal2tiles"));
        Path hillshade = work.resolve("hs.tif");
        run("gdaldem", "hillshade", "-q", "-compute_edges", "-s", "111120", DEM.toString(),
                hillshade.toString());
        Path gdal = work.resolve("tiles");
        run("gdal2tiles.py", "--xyz", "-q", "-z", ZOOMS.min() + "-" + ZOOMS.max(), "-w",
                "none", "--processes=1", hillshade.toString(), gdal.toString());
        Path ours = tiles;
        Set<String> gdalTiles = pngs(gdal);
        assertEquals(gdalTiles, pngs(ours));
        long oursOnly = 0;
        long gdalOnly = 0;
        long opaque = 0;
        for (String t : gdalTiles) {
            BufferedImage a = ImageIO.read(ours.resolve(t).toFile());
            BufferedImage b = ImageIO.read(gdal.resolve(t).toFile());
            for (int y = 0; y < 256; y++) {
                for (int x = 0; x < 256; x++) {
                    boolean dataA = (a.getRGB(x, y) >>> 24) > 0;
                    boolean dataB = (b.getRGB(x, y) >>> 24) > 0;
                    opaque += dataA ? 1 : 0;
                    oursOnly += dataA && !dataB ? 1 : 0;
                    gdalOnly += dataB && !dataA ? 1 : 0;
                }
            }
        }
        // the outline of the DEM at each zoom, in pixels: 2 × (width + height)
        double outline = 0;
        for (int z = ZOOMS.min(); z <= ZOOMS.max(); z++) {
            outline += 2 * (column(EAST, z) - column(WEST, z) + row(SOUTH, z) - row(NORTH, z));
        }
        System.out.printf(java.util.Locale.ROOT, "gdal2tiles agreement: %d data pixels; only ours %d, only GDAL's"
                + " %d, outline %.0f pixels%n", opaque, oursOnly, gdalOnly, outline);
        assertTrue(opaque > 100000, "data pixels: " + opaque);
        // a pixel holds data here when its centre lies on the DEM; GDAL also keeps the pixels the DEM only partly
        // covers, a band along the outline no wider than a pixel
        assertEquals(0, oursOnly, "pixels with data here but not in GDAL's tiles");
        assertTrue(gdalOnly <= outline, gdalOnly + " pixels only GDAL's, along an outline of " + outline);
    }

    private static Set<String> pngs(Path root) throws IOException {
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(p -> p.toString().endsWith(".png")).map(p -> root.relativize(p).toString()
                    .replace(File.separatorChar, '/')).collect(Collectors.toSet());
        }
    }

    static boolean onPath(String program) {
        String path = System.getenv("PATH");
        return path != null && Stream.of(path.split(File.pathSeparator))
                .anyMatch(d -> Files.isExecutable(Path.of(d, program)));
    }

    private static void run(String... command) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(List.of(command)).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), String.join(" ", command) + " did not finish");
        assertEquals(0, p.exitValue(), String.join(" ", command) + ": " + out);
    }
}
