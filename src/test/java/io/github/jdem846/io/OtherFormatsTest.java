package io.github.jdem846.io;

import static io.github.jdem846.io.DemAssertions.assertSameGeotransform;
import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.source.ValueScale;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Sample types, georeferencing variants and the other formats, against the volcano and Luxembourg DEMs they were
 * made from with GDAL (testdata/formats/README.md) or against files written here by hand (SRTM HGT, BIL with two
 * bands, ASCII with cell-centre keys).
 */
class OtherFormatsTest {

    private static final Path FORMATS = Path.of("testdata", "formats");

    @TempDir
    Path tmp;

    /** The volcano DEM with every value mapped by {@code f}. */
    private static Dem volcanoMapped(DoubleUnaryOperator f) {
        Dem v = TestDems.load(TestDems.VOLCANO);
        float[] out = v.backingArray().clone();
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) f.applyAsDouble(out[i]);
        }
        return new Dem(out, v.geometry());
    }

    @ParameterizedTest
    @CsvSource({
        "volcano_uint8.tif, Byte, 1, 0",
        "volcano_int8_minus100.tif, Int8, 1, -100",
        "volcano_int32_minus1000.tif, Int32, 1, -1000",
        "volcano_uint32_times20000000.tif, UInt32, 20000000, 0",
        "volcano_float64_times1.5.tif, Float64, 1.5, 0",
        "volcano_uint8_deflate_pred2.tif, Byte, 1, 0",
        "volcano_int8_minus100_lzw_pred2.tif, Int8, 1, -100",
        "volcano_uint16_times300_lzw_pred2_bigendian.tif, UInt16, 300, 0",
        "volcano_uint32_times20000000_deflate_pred2_tile16.tif, UInt32, 20000000, 0",
        "volcano_2bands_planar_float32_pred3_tile16.tif, Float32, 1, 0.25",
        "volcano_float32_plus0.5_lzw_tile16.tif, Float32, 1, 0.5",
        "volcano_int16_lzw_strip8_bigendian.tif, Int16, 1, 0"})
    void sampleTypesDecodeToTheValuesTheyWereMadeFrom(String name, String type, double scale, double offset)
            throws IOException {
        LoadedDem loaded = DemReader.load(FORMATS.resolve(name), ReadRequest.FULL);
        assertEquals(type, loaded.info().dataType().displayName());
        assertSameValues(volcanoMapped(v -> v * scale + offset), loaded.dem(), name);
        assertSameGeotransform(TestDems.load(TestDems.VOLCANO).geometry(), loaded.dem().geometry(), 0, name);
    }

    @Test
    void unsignedSixteenBitAboveThe32767SignedLimitWithNoData() throws IOException {
        LoadedDem loaded = DemReader.load(FORMATS.resolve("volcano_uint16_times300_nodata65535.tif"),
                ReadRequest.FULL);
        assertEquals(SampleType.UINT16, loaded.info().dataType());
        assertEquals(65535.0, loaded.info().declaredNoData());
        Dem expected = volcanoMapped(v -> v * 300);
        float[] e = expected.backingArray();
        e[0] = Float.NaN;                       // cells set to 65535 by make_formats.py
        e[e.length - 1] = Float.NaN;
        assertSameValues(expected, loaded.dem(), "uint16");
        assertEquals(58500, loaded.dem().statistics().max());
    }

    @Test
    void gdalScaleAndOffsetUnpackDecimetresAfterTheRawNoDataRule() throws IOException {
        // Stored as Int16 decimetres above 50 m (raw = (v − 50) × 10), GDAL scale 0.1 and offset 50, and raw 440
        // (= the volcano's lowest value, 94 m) declared as no-data: those cells are missing, all others are v.
        Path file = FORMATS.resolve("volcano_int16_decimetres_scale0.1_offset50_nodata440.tif");
        LoadedDem loaded = DemReader.load(file, ReadRequest.FULL);
        Dem expected = volcanoMapped(v -> v == 94 ? Double.NaN : v);
        assertSameValues(expected, loaded.dem(), "unpacked");
        assertEquals(51, loaded.dem().statistics().noDataCount());
        assertEquals(95, loaded.dem().statistics().min());
        assertTrue(loaded.info().notices().stream().anyMatch(n -> n.contains("raw × 0.1 + 50")),
                loaded.info().notices().toString());
        // The same through a window.
        assertSameValues(expected.crop(7, 9, 30, 41), DemReader.read(file, ReadRequest.of(Window.cells(7, 9, 30,
                41))), "window");
    }

    @Test
    void gdalMetadataWithoutScaleOrWithUnusableValuesChangesNothing() {
        java.util.List<String> notices = new java.util.ArrayList<>();
        assertTrue(ValueScale.fromGdalMetadata(null, notices).isIdentity());
        assertTrue(ValueScale.fromGdalMetadata("<GDALMetadata><Item name=\"AREA_OR_POINT\">Area</Item>"
                + "</GDALMetadata>", notices).isIdentity());
        assertTrue(notices.isEmpty(), notices.toString());
        // Band 2's scale is not band 1's; a zero scale and an unparsable offset are ignored with notices.
        assertTrue(ValueScale.fromGdalMetadata("<GDALMetadata><Item name=\"SCALE\" sample=\"1\" role=\"scale\">"
                + "0.5</Item></GDALMetadata>", notices).isIdentity());
        ValueScale s = ValueScale.fromGdalMetadata("<GDALMetadata><Item name=\"SCALE\" sample=\"0\" role=\"scale\">"
                + "0</Item><Item name=\"OFFSET\" sample=\"0\" role=\"offset\">x</Item></GDALMetadata>", notices);
        assertTrue(s.isIdentity());
        assertEquals(2, notices.size(), notices.toString());
        // Broken XML is reported when it could hold a scale or an offset, and not parsed at all otherwise.
        assertTrue(ValueScale.fromGdalMetadata("<not xml role=\"scale\"", notices).isIdentity());
        assertEquals(3, notices.size(), notices.toString());
        assertTrue(ValueScale.fromGdalMetadata("<not xml", notices).isIdentity());
        assertEquals(3, notices.size(), notices.toString());
    }

    @Test
    void twoBandsGiveBandOneWithANotice() throws IOException {
        LoadedDem loaded = DemReader.load(FORMATS.resolve("volcano_2bands.tif"), ReadRequest.FULL);
        assertSameValues(TestDems.load(TestDems.VOLCANO), loaded.dem(), "band 1");
        assertEquals(2, loaded.info().bands());
        assertTrue(loaded.info().notices().stream().anyMatch(n -> n.contains("2 bands")), loaded.info().notices()
                .toString());
    }

    @Test
    void planarTwoBandFileGivesBandOneInEveryWindow() throws IOException {
        Path file = FORMATS.resolve("volcano_2bands_planar_tile16.tif");
        Dem volcano = TestDems.load(TestDems.VOLCANO);
        assertSameValues(volcano, DemReader.read(file), "planar band 1");
        assertSameValues(volcano.crop(5, 17, 23, 40), DemReader.read(file, ReadRequest.of(Window.cells(5, 17, 23,
                40))), "planar window across tile edges");
    }

    /** The volcano with cells {@code [col0, col1) × [row0, row1)} set to {@code value}. */
    private static Dem volcanoWith(float value, int col0, int row0, int col1, int row1, Dem base) {
        float[] out = base.backingArray().clone();
        for (int r = row0; r < row1; r++) {
            java.util.Arrays.fill(out, r * base.width() + col0, r * base.width() + col1, value);
        }
        return new Dem(out, base.geometry());
    }

    @Test
    void sparseTilesReadAsNoDataInEveryWindow() throws IOException {
        // SPARSE_OK left out 4 whole tiles and the partial south-east tile (make_formats.py): offsets and counts 0.
        Path file = FORMATS.resolve("volcano_sparse_tile16_nodata.tif");
        Dem volcano = TestDems.load(TestDems.VOLCANO);
        Dem expected = volcanoWith(Float.NaN, 48, 80, 61, 87, volcanoWith(Float.NaN, 16, 16, 48, 48, volcano));
        assertSameValues(expected, DemReader.read(file), "whole file");
        for (Window.Cells w : new Window.Cells[] {Window.cells(5, 10, 40, 30), Window.cells(20, 20, 8, 8),
            Window.cells(40, 60, 21, 27), Window.cells(0, 47, 61, 2)}) {
            assertSameValues(expected.crop(w.col(), w.row(), w.width(), w.height()),
                    DemReader.read(file, ReadRequest.of(w)), "window " + w);
        }
    }

    @Test
    void sparseStripsWithoutNoDataReadAsZero() throws IOException {
        Path file = FORMATS.resolve("volcano_sparse_strip8_zeros.tif");
        Dem volcano = TestDems.load(TestDems.VOLCANO);
        Dem expected = volcanoWith(0f, 0, 8, 61, 24, volcano);
        assertSameValues(expected, DemReader.read(file), "whole file");
        assertSameValues(expected.crop(3, 5, 50, 30), DemReader.read(file, ReadRequest.of(Window.cells(3, 5, 50,
                30))), "window across the sparse strips");
    }

    @Test
    void jpegCompressedTiffIsReadWithoutSubsetting() throws IOException {
        // JPEG is lossy (up to 5 m off the source here): compare with GDAL's decode of the same file
        // (testdata/golden/readers/README.md), and check the loss is small.
        Path file = FORMATS.resolve("volcano_uint8_jpeg_q95.tif");
        Dem full = DemReader.read(file);
        assertSameValues(DemReader.read(Path.of("testdata/golden/readers/volcano_uint8_jpeg_q95_gdal.asc")), full,
                "JPEG decode vs GDAL");
        Dem volcano = TestDems.load(TestDems.VOLCANO);
        for (int i = 0; i < volcano.backingArray().length; i++) {
            assertEquals(volcano.backingArray()[i], full.backingArray()[i], 5, "cell " + i);
        }
        assertSameValues(full.crop(5, 17, 23, 40), DemReader.read(file, ReadRequest.of(Window.cells(5, 17, 23,
                40))), "JPEG window");
    }

    @Test
    void pixelIsPointGivesTheSameCornerGeometry() throws IOException {
        DemInfo area = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.VOLCANO + ".tif"));
        DemInfo point = DemReader.inspect(FORMATS.resolve("volcano_pixelispoint.tif"));
        assertSameGeotransform(area.geometry(), point.geometry(), 0, "PixelIsPoint");
        assertEquals(PixelAnchor.CENTER, point.geometry().declaredAnchor());
        assertEquals(PixelAnchor.CORNER, area.geometry().declaredAnchor());
    }

    @Test
    void rotatedGridIsRefused() {
        DemFormatException e = assertThrows(DemFormatException.class,
                () -> DemReader.read(FORMATS.resolve("volcano_rotated.tif")));
        assertTrue(e.getMessage().contains("rotated or sheared"), e.getMessage());
        assertTrue(e.getMessage().contains("volcano_rotated.tif"), e.getMessage());
    }

    @Test
    void usSurveyFootFromProjLinearUnitsGeoKeyWhenSisCannotResolveTheCode() throws IOException {
        for (String name : new String[] {"volcano_epsg2227_ftus.tif", "volcano_userdefined_tm_ftus.tif"}) {
            GridGeometry g = DemReader.inspect(FORMATS.resolve(name)).geometry();
            assertEquals(CrsInfo.Kind.PROJECTED, g.crs().kind(), name);
            assertEquals(1200.0 / 3937.0, g.crs().linearUnitMeters(), 1e-15, name);
            assertEquals(10 * 1200.0 / 3937.0, g.cellWidthMeters(40), 1e-12, name);
            assertTrue(g.geoLocator().isEmpty(), name + ": no lat/lon without a SIS CRS");
        }
        assertEquals(2227, DemReader.inspect(FORMATS.resolve("volcano_epsg2227_ftus.tif")).geometry().crs().epsg());
        assertEquals("GRS 1980", DemReader.inspect(FORMATS.resolve("volcano_userdefined_tm_ftus.tif")).geometry()
                .crs().ellipsoid().name(), "GeogEllipsoidGeoKey 7019");
    }

    @Test
    void nztmGeoTiffFallsBackOnGeoKeys() throws IOException {
        DemInfo info = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.VOLCANO + ".tif"));
        CrsInfo crs = info.geometry().crs();
        assertEquals(2193, crs.epsg());
        assertEquals(CrsInfo.Kind.PROJECTED, crs.kind());
        assertEquals(1.0, crs.linearUnitMeters());
        assertEquals("NZGD2000 / New Zealand Transverse Mercator 2000", crs.name());
        assertTrue(info.notices().stream().anyMatch(n -> n.contains("EPSG:2193")), info.notices().toString());
    }

    @Test
    void asciiAndBilEqualTheDatasets() throws IOException {
        for (String name : new String[] {"volcano.asc", "volcano.bil"}) {
            Dem dem = DemReader.read(FORMATS.resolve(name));
            Dem ref = TestDems.load(TestDems.VOLCANO);
            assertSameValues(ref, dem, name);
            assertSameGeotransform(ref.geometry(), dem.geometry(), 1e-12, name);
            assertEquals(CrsInfo.Kind.PROJECTED, dem.geometry().crs().kind(), name + " .prj");
        }
        for (String name : new String[] {"luxembourg.asc", "luxembourg.bil"}) {
            Dem dem = DemReader.read(FORMATS.resolve(name));
            Dem ref = TestDems.load(TestDems.LUXEMBOURG);
            assertEquals(3942, dem.statistics().noDataCount(), name);
            assertSameValues(ref, dem, name);
            assertSameGeotransform(ref.geometry(), dem.geometry(), 1e-9, name);
        }
        assertEquals(PixelAnchor.CENTER, DemReader.inspect(FORMATS.resolve("volcano.bil")).geometry()
                .declaredAnchor(), "ULXMAP/ULYMAP name the centre of the upper-left cell");
        assertEquals(DemFormat.ESRI_ASCII, DemReader.inspect(FORMATS.resolve("volcano.asc")).format());
        assertEquals(DemFormat.BIL, DemReader.inspect(FORMATS.resolve("volcano.bil")).format());
    }

    @Test
    void srtmHgtFromTheFileName() throws IOException {
        int n = 1201;
        ByteBuffer b = ByteBuffer.allocate(n * n * 2).order(ByteOrder.BIG_ENDIAN);
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < n; c++) {
                b.putShort((short) (r == 5 && c == 7 ? -32768 : (r * 7 + c * 3) % 3000 - 100));
            }
        }
        Path hgt = tmp.resolve("S36W085.hgt");
        Files.write(hgt, b.array());
        LoadedDem loaded = DemReader.load(hgt, ReadRequest.FULL);
        Dem dem = loaded.dem();
        assertEquals(DemFormat.SRTM_HGT, loaded.info().format());
        assertEquals(n, dem.width());
        assertEquals(n, dem.height());
        assertEquals(-100, dem.get(0, 0));
        assertEquals((1200 * 7 + 1199 * 3) % 3000 - 100, dem.get(1199, 1200));
        assertTrue(Float.isNaN(dem.get(7, 5)));
        assertEquals(1, dem.statistics().noDataCount());
        // S36W085: centre of the south-west sample at 36°S 85°W, 3″ spacing, so the outer corner is 1.5″ out.
        GridGeometry g = dem.geometry();
        double cell = 3.0 / 3600;
        assertEquals(cell, g.cellWidth(), 1e-15);
        assertEquals(-85 - cell / 2, g.originX(), 1e-12);
        assertEquals(-35 + cell / 2, g.originY(), 1e-12);
        assertEquals(-36 - cell / 2, g.southY(), 1e-12);
        assertEquals(-84 + cell / 2, g.eastX(), 1e-12);
        assertEquals(-85.0, g.centerX(0), 1e-12);
        assertEquals(-36.0, g.centerY(n - 1), 1e-12);
        assertEquals(4326, g.crs().epsg());
        assertTrue(g.crs().isGeographic());
        assertEquals(PixelAnchor.CENTER, g.declaredAnchor());
    }

    @Test
    void srtmHgtOfAWrongSizeOrNameIsRefused() throws IOException {
        Path wrongSize = tmp.resolve("N34W118.hgt");
        Files.write(wrongSize, new byte[1000]);
        DemFormatException e1 = assertThrows(DemFormatException.class, () -> DemReader.read(wrongSize));
        assertTrue(e1.getMessage().contains("1000 bytes") && e1.getMessage().contains("2884802"), e1.getMessage());
        Path wrongName = tmp.resolve("tile.hgt");
        Files.write(wrongName, new byte[1201 * 1201 * 2]);
        DemFormatException e2 = assertThrows(DemFormatException.class, () -> DemReader.read(wrongName));
        assertTrue(e2.getMessage().contains("N34W118.hgt"), e2.getMessage());
    }

    @Test
    void asciiWithCellCentreKeysNanAndLineBreaksAnywhere() throws IOException {
        Path asc = tmp.resolve("grid.txt");
        Files.writeString(asc, """
                NCOLS 3
                NROWS 2
                XLLCENTER 100.5
                YLLCENTER 200.5
                CELLSIZE 1
                NODATA_VALUE -1
                1 2
                -1 4 nan
                6
                """, StandardCharsets.US_ASCII);
        LoadedDem loaded = DemReader.load(asc, ReadRequest.FULL);
        Dem dem = loaded.dem();
        assertEquals(DemFormat.ESRI_ASCII, loaded.info().format());
        assertEquals(1, dem.get(0, 0));
        assertEquals(2, dem.get(1, 0));
        assertTrue(Float.isNaN(dem.get(2, 0)), "declared -1");
        assertEquals(4, dem.get(0, 1));
        assertTrue(Float.isNaN(dem.get(1, 1)), "nan");
        assertEquals(6, dem.get(2, 1));
        assertEquals(100, dem.geometry().originX(), 0);
        assertEquals(202, dem.geometry().originY(), 0);
        assertEquals(PixelAnchor.CENTER, dem.geometry().declaredAnchor());
        assertEquals(CrsInfo.Kind.UNKNOWN, dem.geometry().crs().kind(), "no .prj and y 200–202 is not a latitude");
    }

    @Test
    void bilWithTwoBandsSkipBytesAndMotorolaOrderReadsBandOne() throws IOException {
        int cols = 4;
        int rows = 3;
        int skip = 10;
        ByteBuffer b = ByteBuffer.allocate(skip + rows * cols * 2 * 2).order(ByteOrder.BIG_ENDIAN);
        b.position(skip);
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                b.putShort((short) (1000 + r * 10 + c));   // band 1
            }
            for (int c = 0; c < cols; c++) {
                b.putShort((short) -5);                    // band 2
            }
        }
        Files.write(tmp.resolve("two.bil"), b.array());
        Files.writeString(tmp.resolve("two.hdr"), String.join("\n", "BYTEORDER M", "LAYOUT BIL", "NROWS 3",
                "NCOLS 4", "NBANDS 2", "NBITS 16", "SKIPBYTES 10", "BANDROWBYTES 8", "TOTALROWBYTES 16",
                "PIXELTYPE SIGNEDINT", "ULXMAP 500010", "ULYMAP 4000010", "XDIM 20", "YDIM 20", "NODATA 1011"));
        LoadedDem loaded = DemReader.load(tmp.resolve("two.bil"), ReadRequest.FULL);
        Dem dem = loaded.dem();
        assertEquals(1000, dem.get(0, 0));
        assertEquals(1023, dem.get(3, 2));
        assertTrue(Float.isNaN(dem.get(1, 1)), "NODATA 1011");
        assertEquals(500000, dem.geometry().originX(), 0);
        assertEquals(4000020, dem.geometry().originY(), 0);
        assertEquals(2, loaded.info().bands());
        assertEquals(CrsInfo.Kind.UNKNOWN, dem.geometry().crs().kind(), "no .prj and not degrees");
        assertNull(loaded.info().geometry().crs().name());
    }
}
