package io.github.jdem846.io;

import static io.github.jdem846.io.DemAssertions.assertSameGeotransform;
import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.testing.DemTiles;
import io.github.jdem846.testing.DemTiles.Cut;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Several files read as one grid: tiles cut from the real DEMs of testdata/dem read back cell for cell as the DEM
 * they were cut from, whole, through windows, decimated and in parallel bands; gaps, overlaps and files that do
 * not fit together.
 */
class MosaicReadTest {

    private static final Path DEM = Path.of("testdata", "dem");
    private static final Path TUJUNGA = DEM.resolve("bigtujunga_srtm30m_utm11n.flt");
    private static final Path JACKSBORO = DEM.resolve("jacksboro_srtm3s_wgs84.tif");

    @TempDir
    static Path tmp;

    private static Dem tujunga;
    private static List<Path> tujungaTiles;

    @BeforeAll
    static void cut() throws IOException {
        tujunga = DemReader.read(TUJUNGA);
        // split off the middle, SRTM-like: the western and northern tiles share a column and a row with the others
        tujungaTiles = DemTiles.gridFloat(tujunga, DemTiles.quarters(1197, 643, 601, 322, 1), tmp, "tujunga",
                DEM.resolve("bigtujunga_srtm30m_utm11n.prj"));
    }

    @Test
    void fourGridFloatTilesReadAsTheDemTheyWereCutFrom() throws IOException {
        LoadedDem mosaic = DemReader.load(DemInput.of(tujungaTiles), ReadRequest.FULL);
        assertSameValues(tujunga, mosaic.dem(), "mosaic of 4 GridFloat tiles");
        assertSameGeotransform(tujunga.geometry(), mosaic.dem().geometry(), 1e-12, "mosaic");
        assertEquals(tujunga.geometry().crs().epsg(), mosaic.dem().geometry().crs().epsg());
        DemInfo info = mosaic.info();
        assertEquals(DemFormat.MOSAIC, info.format());
        assertEquals(4, info.members().size());
        assertEquals(tujungaTiles, info.members());
        assertTrue(info.notices().stream().anyMatch(n -> n.contains("overlap") && n.contains("mean")),
                info.notices().toString());
        assertFalse(info.notices().stream().anyMatch(n -> n.contains("uncovered")), info.notices().toString());
        assertEquals(SampleType.FLOAT32, info.dataType());
    }

    @Test
    void geographicGeoTiffTilesReadAsTheDemTheyWereCutFrom() throws IOException {
        Dem whole = DemReader.read(JACKSBORO);
        List<Cut> cuts = DemTiles.quarters(403, 344, 200, 170, 1);
        List<Path> tiles = DemTiles.geoTiff(whole, cuts, tmp, "jacksboro", 4326, true);
        LoadedDem mosaic = DemReader.load(DemInput.of(tiles), ReadRequest.FULL);
        assertSameValues(whole, mosaic.dem(), "mosaic of 4 GeoTIFF tiles");
        assertEquals(whole.geometry().originX(), mosaic.dem().geometry().originX(), "west edge, exactly");
        assertEquals(whole.geometry().originY(), mosaic.dem().geometry().originY(), "north edge, exactly");
        assertEquals(whole.geometry().cellWidth(), mosaic.dem().geometry().cellWidth());
        assertTrue(mosaic.dem().geometry().crs().isGeographic());
        // the tiles in another order make the same grid
        List<Path> shuffled = List.of(tiles.get(3), tiles.get(1), tiles.get(2), tiles.get(0));
        assertSameValues(whole, DemReader.read(DemInput.of(shuffled), ReadRequest.FULL), "other order");
    }

    @Test
    void windowsDecimationStatisticsAndParallelBandsMatchTheWholeDem() throws IOException {
        DemInput mosaic = DemInput.of(tujungaTiles);
        List<ReadRequest> requests = List.of(
                ReadRequest.of(Window.cells(590, 310, 40, 30)),     // across both seams
                ReadRequest.of(Window.cells(0, 0, 300, 200)),       // inside one tile
                ReadRequest.of(Window.cells(601, 0, 596, 643)),     // the eastern tiles exactly
                new ReadRequest(Window.cells(3, 5, 1190, 630), 3),  // decimated, blocks across the seams
                new ReadRequest(null, 7));
        for (ReadRequest r : requests) {
            LoadedDem a = DemReader.load(DemInput.of(TUJUNGA), r);
            LoadedDem b = DemReader.load(mosaic, r);
            assertSameValues(a.dem(), b.dem(), r.toString());
            assertSameGeotransform(a.dem().geometry(), b.dem().geometry(), 1e-12, r.toString());
            assertEquals(a.sourceStatistics(), b.sourceStatistics(), r.toString());
        }
        ElevationStatistics whole = DemReader.statistics(TUJUNGA);
        assertEquals(whole, DemReader.statistics(mosaic));
        // in two bands at once, each through a mosaic of its own
        LoadedDem parallel = DemReader.load(mosaic, ReadRequest.FULL, 2, 1000);
        assertSameValues(tujunga, parallel.dem(), "two parallel bands");
        assertEquals(whole, DemReader.statistics(mosaic, 2, 1000));
    }

    @Test
    void aMissingTileIsAGapOfNoData() throws IOException {
        List<Path> three = List.of(tujungaTiles.get(0), tujungaTiles.get(1), tujungaTiles.get(2));
        LoadedDem m = DemReader.load(DemInput.of(three), ReadRequest.FULL);
        assertEquals(1197, m.dem().width());
        assertEquals(643, m.dem().height());
        long gap = 0;
        for (int r = 0; r < 643; r++) {
            for (int c = 0; c < 1197; c++) {
                boolean inGap = c >= 602 && r >= 323; // the south-east tile less the shared column and row
                float v = m.dem().get(c, r);
                if (inGap) {
                    assertTrue(Float.isNaN(v), "gap at " + c + "," + r);
                    gap++;
                } else {
                    assertEquals(tujunga.get(c, r), v, "cell " + c + "," + r);
                }
            }
        }
        long expected = (1197L - 602) * (643 - 323);
        assertEquals(expected, gap);
        assertTrue(m.info().notices().contains("the files leave " + expected + " cells of the grid uncovered: they"
                + " read as no-data"), m.info().notices().toString());
        assertEquals(expected, m.sourceStatistics().noDataCount());
    }

    @Test
    void overlappingCellsAreTheMeanOfTheValidValues() throws IOException {
        // two tiles sharing 3 columns: the eastern one 2 m higher there, and with a hole of no-data
        Cut west = new Cut(0, 0, 103, 50);
        Cut east = new Cut(100, 0, 100, 50);
        float[] w = DemTiles.cells(tujunga, west);
        float[] e = DemTiles.cells(tujunga, east);
        for (int i = 0; i < e.length; i++) {
            e[i] += 2;
        }
        e[10 * 100 + 1] = DemTiles.NO_DATA;            // (101, 10): only the western value is valid
        w[20 * 103 + 102] = DemTiles.NO_DATA;          // (102, 20): only the eastern value is valid
        Path a = tmp.resolve("mean_a.flt");
        Path b = tmp.resolve("mean_b.flt");
        DemTiles.writeGridFloat(a, w, tujunga.geometry(), west, null);
        DemTiles.writeGridFloat(b, e, tujunga.geometry(), east, null);
        Dem m = DemReader.read(DemInput.of(List.of(a, b)), ReadRequest.FULL);
        assertEquals(200, m.width());
        for (int r = 0; r < 50; r++) {
            for (int c = 0; c < 200; c++) {
                float v = tujunga.get(c, r);
                float expected = c < 100 ? v : c >= 103 ? v + 2 : (float) (((double) v + (v + 2)) / 2);
                if (c == 101 && r == 10) {
                    expected = v;
                } else if (c == 102 && r == 20) {
                    expected = v + 2;
                }
                assertEquals(expected, m.get(c, r), "cell " + c + "," + r);
            }
        }
    }

    @Test
    void aFileGivenTwiceIsReadOnceAndAHeaderStandsForItsData() throws IOException {
        List<Path> files = new ArrayList<>(tujungaTiles);
        files.add(DemTiles.sibling(tujungaTiles.get(2), "hdr"));
        DemInfo info = DemReader.inspect(DemInput.of(files));
        assertEquals(4, info.members().size());
        assertTrue(info.notices().stream().anyMatch(n -> n.contains("given more than once")), info.notices()
                .toString());
    }

    @Test
    void filesOfAMosaicAreEveryTileAndItsSidecars() throws IOException {
        List<Path> files = DemReader.filesOf(DemInput.of(tujungaTiles));
        assertEquals(12, files.size(), files.toString());
        for (Path t : tujungaTiles) {
            assertTrue(files.contains(t) && files.contains(DemTiles.sibling(t, "hdr"))
                    && files.contains(DemTiles.sibling(t, "prj")), t.toString());
        }
    }

    @Test
    void tilesOfAnotherCrsAreRefusedNamingBothFiles() throws IOException {
        Path other = tmp.resolve("crs");
        Files.createDirectories(other);
        List<Path> t = DemTiles.gridFloat(tujunga, List.of(new Cut(601, 0, 596, 323)), other, "utm10",
                null);
        // UTM zone 10 instead of 11: same units, same numbers, another CRS
        Files.writeString(DemTiles.sibling(t.get(0), "prj"), Files.readString(DEM.resolve(
                "bigtujunga_srtm30m_utm11n.prj")).replace("Zone_11N", "Zone_10N").replace("-117.0", "-123.0"));
        DemFormatException e = assertThrows(DemFormatException.class,
                () -> DemReader.read(DemInput.of(List.of(tujungaTiles.get(0), t.get(0))), ReadRequest.FULL));
        String m = e.getMessage();
        assertTrue(m.startsWith(t.get(0).toString()) && m.contains(tujungaTiles.get(0).toString())
                && m.contains("must share one CRS"), m);
    }

    @Test
    void tilesOfAnotherCellSizeOrOffTheGridAreRefused() throws IOException {
        Path dir = Files.createDirectories(tmp.resolve("misfit"));
        Cut cut = new Cut(601, 0, 596, 323);
        Path coarse = dir.resolve("coarse.flt");
        DemTiles.writeGridFloat(coarse, DemTiles.cells(tujunga, cut), tujunga.geometry(), cut,
                DEM.resolve("bigtujunga_srtm30m_utm11n.prj"));
        Path hdr = DemTiles.sibling(coarse, "hdr");
        Files.writeString(hdr, Files.readString(hdr).replace("cellsize 30", "cellsize 90"));
        DemFormatException e1 = assertThrows(DemFormatException.class,
                () -> DemReader.inspect(DemInput.of(List.of(tujungaTiles.get(0), coarse))));
        assertTrue(e1.getMessage().contains("has cells of 90 × 90, but " + tujungaTiles.get(0)
                + " has cells of 30 × 30"), e1.getMessage());

        Path shifted = dir.resolve("shifted.flt");
        DemTiles.writeGridFloat(shifted, DemTiles.cells(tujunga, cut), tujunga.geometry().window(0, 0, 1, 1)
                .withCrs(tujunga.geometry().crs()), cut, DEM.resolve("bigtujunga_srtm30m_utm11n.prj"));
        Path sh = DemTiles.sibling(shifted, "hdr");
        double xll = tujunga.geometry().originX() + 601 * 30;
        Files.writeString(sh, Files.readString(sh).replace(DemTiles.plain(xll), DemTiles.plain(xll + 7.5)));
        DemFormatException e2 = assertThrows(DemFormatException.class,
                () -> DemReader.inspect(DemInput.of(List.of(tujungaTiles.get(0), shifted))));
        assertTrue(e2.getMessage().contains("is not on the grid of " + tujungaTiles.get(0))
                && e2.getMessage().contains("0.250 cells off"), e2.getMessage());

        Path far = dir.resolve("far.flt");
        DemTiles.writeGridFloat(far, DemTiles.cells(tujunga, cut), tujunga.geometry(), cut,
                DEM.resolve("bigtujunga_srtm30m_utm11n.prj"));
        Path fh = DemTiles.sibling(far, "hdr");
        String farWest = DemTiles.plain(xll + 30.0 * 3_000_000_000L); // 3·10⁹ cells east: past the int range
        Files.writeString(fh, Files.readString(fh).replace(DemTiles.plain(xll), farWest));
        DemFormatException e3 = assertThrows(DemFormatException.class,
                () -> DemReader.inspect(DemInput.of(List.of(tujungaTiles.get(0), far))));
        assertTrue(e3.getMessage().contains("more than 2147483647 on a side"), e3.getMessage());
    }

    @Test
    void aWindowNeverOpensTheTilesOutsideIt() throws IOException {
        // the south-east tile's header is sound but its pixels are not: a Deflate strip of garbage
        Path dir = Files.createDirectories(tmp.resolve("corrupt"));
        List<Path> files = new ArrayList<>(tujungaTiles.subList(0, 3));
        Cut se = new Cut(601, 322, 596, 321);
        Path bad = dir.resolve("se.tif");
        var g = tujunga.geometry().window(se.col(), se.row(), se.width(), se.height());
        byte[] tiff = io.github.jdem846.testing.TinyTiff.int16(se.width(), se.height())
                .data(java.util.Arrays.copyOf(new byte[] {1, 2, 3, 4, 5, 6, 7, 8}, 4096))
                .set(258, io.github.jdem846.testing.TinyTiff.SHORT, 32)
                .set(339, io.github.jdem846.testing.TinyTiff.SHORT, 3)
                .set(259, io.github.jdem846.testing.TinyTiff.SHORT, 8)
                .set(279, io.github.jdem846.testing.TinyTiff.LONG, 4096)
                .georeferenced(g.originX(), g.originY(), 30, 30)
                .set(34735, io.github.jdem846.testing.TinyTiff.SHORT, 1, 1, 0, 3, 1024, 0, 1, 1, 1025, 0, 1, 1,
                        3072, 0, 1, 32611)
                .bytes();
        Files.write(bad, tiff);
        files.add(bad);
        DemInput mosaic = DemInput.of(files);
        // the north half, across the other seam: read without touching the corrupt tile
        ReadRequest north = ReadRequest.of(Window.cells(0, 0, 1197, 300));
        assertSameValues(DemReader.read(TUJUNGA, north), DemReader.read(mosaic, north), "north half");
        DemFormatException e = assertThrows(DemFormatException.class,
                () -> DemReader.read(mosaic, ReadRequest.of(Window.cells(590, 310, 40, 30))));
        assertTrue(e.getMessage().startsWith(bad.toString()) && e.getMessage().contains("cannot decode"),
                e.getMessage());
    }

    @Test
    void twoSrtmTilesShareTheirEdgeColumn() throws IOException {
        // Jacksboro's 3" cells lie on the posts of N36W085.hgt (columns 704-1106, rows 321-664); the rest of the
        // pair, and all of N36W084.hgt, is SRTM's no-data
        Dem j = DemReader.read(JACKSBORO);
        int n = 1201;
        java.nio.ByteBuffer west = java.nio.ByteBuffer.allocate(n * n * 2);
        java.nio.ByteBuffer east = java.nio.ByteBuffer.allocate(n * n * 2);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                boolean in = c >= 704 && c < 704 + 403 && r >= 321 && r < 321 + 344;
                west.putShort((short) (in ? j.get(c - 704, r - 321) : -32768));
                east.putShort((short) -32768);
            }
        }
        Path dir = Files.createDirectories(tmp.resolve("srtm"));
        Path w = Files.write(dir.resolve("N36W085.hgt"), west.array());
        Path e = Files.write(dir.resolve("N36W084.hgt"), east.array());
        LoadedDem pair = DemReader.load(DemInput.of(List.of(e, w)), ReadRequest.FULL);
        var g = pair.dem().geometry();
        assertEquals(2401, g.width(), "two tiles of 1201 posts sharing one column");
        assertEquals(1201, g.height());
        double cell = 1.0 / 1200;
        assertEquals(-85 - cell / 2, g.originX(), 1e-12);
        assertEquals(-83 + cell / 2, g.eastX(), 1e-12);
        assertEquals(37 + cell / 2, g.originY(), 1e-12);
        assertEquals(DemFormat.MOSAIC, pair.info().format());
        assertEquals(SampleType.INT16, pair.info().dataType());
        assertEquals(j.statistics().validCount(), pair.sourceStatistics().validCount());
        Window box = new Window.World(j.geometry().originX(), j.geometry().southY(), j.geometry().eastX(),
                j.geometry().originY());
        Dem read = DemReader.read(DemInput.of(List.of(w, e)), ReadRequest.of(box));
        assertSameValues(j, read, "Jacksboro's box of the pair");
    }
}
