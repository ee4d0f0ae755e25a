package io.github.jdem846.output;

import io.github.jdem846.internal.GeoKeys;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.testing.TestDems;
import java.awt.image.BufferedImage;
import java.awt.image.DataBuffer;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * GeoTIFFs read back with TwelveMonkeys: pixels exact, tags present with the values worked out by hand from the
 * GeoTIFF 1.1 and TIFF 6.0 specifications.
 */
class GeoTiffOutputTest {

    @TempDir
    Path dir;

    private static final int COMPRESSION = 259;
    private static final int PHOTOMETRIC = 262;
    private static final int BITS_PER_SAMPLE = 258;
    private static final int SAMPLES_PER_PIXEL = 277;
    private static final int EXTRA_SAMPLES = 338;
    private static final int SAMPLE_FORMAT = 339;
    private static final int PREDICTOR = 317;
    private static final int MODEL_PIXEL_SCALE = 33550;
    private static final int MODEL_TIEPOINT = 33922;
    private static final int GDAL_NODATA = 42113;

    /** Big Tujunga (UTM 11N) shown at 598 × 321 pixels: pixel size = extent / image size. */
    @Test
    void grayGeoTiffCarriesGeoreferencingCrsAndNoData() throws IOException {
        GeoReference geo = GeoReference.of(TestDems.load(TestDems.BIG_TUJUNGA).geometry());
        byte[] gray = new byte[598 * 321];
        new Random(1).nextBytes(gray);
        Path file = dir.resolve("shade.tif");
        WriteResult result = ImageOutput.writeGray(file, gray, 598, 321, geo, WriteOptions.defaults().withNoData(0));
        assertTrue(result.sidecars().isEmpty(), "a GeoTIFF embeds its georeferencing");
        assertTrue(result.notices().isEmpty(), result.notices().toString());

        Raster back = TiffTags.raster(file);
        assertEquals(1, back.getNumBands());
        int[] samples = back.getSamples(0, 0, 598, 321, 0, (int[]) null);
        for (int i = 0; i < gray.length; i++) {
            assertEquals(gray[i] & 0xFF, samples[i], "pixel " + i);
        }

        TiffTags tags = TiffTags.read(file);
        assertEquals(8, tags.number(COMPRESSION)); // Adobe Deflate
        assertEquals(1, tags.number(PHOTOMETRIC)); // BlackIsZero
        assertEquals(8, tags.number(BITS_PER_SAMPLE));
        assertEquals(2, tags.number(PREDICTOR)); // horizontal differencing
        // hdr: xllcorner 376313.6554542635, yllcorner 3788627.8276283755, 1197 × 643 cells of 30 m
        assertArrayEquals(new double[]{1197 * 30.0 / 598, 643 * 30.0 / 321, 0}, tags.numbers(MODEL_PIXEL_SCALE),
                1e-9);
        assertArrayEquals(new double[]{0, 0, 0, 376313.6554542635, 3788627.8276283755 + 643 * 30, 0},
                tags.numbers(MODEL_TIEPOINT), 1e-6);
        assertEquals(1, tags.geoKey(GeoKeys.GT_MODEL_TYPE)); // projected
        assertEquals(1, tags.geoKey(GeoKeys.GT_RASTER_TYPE)); // PixelIsArea
        assertEquals(32611, tags.geoKey(GeoKeys.PROJECTED_CS_TYPE));
        assertEquals(9001, tags.geoKey(GeoKeys.PROJ_LINEAR_UNITS)); // metre
        assertEquals("0", tags.text(GDAL_NODATA));
    }

    @Test
    void float32GeoTiffKeepsEveryValueIncludingNaN() throws IOException {
        int w = 53;
        int h = 31;
        float[] values = new float[w * h];
        Random random = new Random(2);
        for (int i = 0; i < values.length; i++) {
            values[i] = (float) (random.nextGaussian() * 1000);
        }
        values[0] = Float.NaN;
        values[1] = -0.0f;
        values[2] = Float.MAX_VALUE;
        values[3] = -Float.MIN_VALUE;
        values[4] = Float.NEGATIVE_INFINITY;
        GeoReference geo = new GeoReference(-84.41375, 36.73291666666667, -84.07791666666667, 36.44625,
                CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84));
        Path file = dir.resolve("depth.tiff");
        ImageOutput.writeFloat(file, values, w, h, geo, WriteOptions.defaults().withNoData(Double.NaN));

        Raster back = TiffTags.raster(file);
        assertEquals(DataBuffer.TYPE_FLOAT, back.getSampleModel().getDataType());
        float[] read = back.getSamples(0, 0, w, h, 0, (float[]) null);
        for (int i = 0; i < values.length; i++) {
            assertEquals(Float.floatToRawIntBits(values[i]), Float.floatToRawIntBits(read[i]), "pixel " + i);
        }
        TiffTags tags = TiffTags.read(file);
        assertEquals(32, tags.number(BITS_PER_SAMPLE));
        assertEquals(3, tags.number(SAMPLE_FORMAT)); // IEEE floating point
        assertEquals(8, tags.number(COMPRESSION));
        assertArrayEquals(new double[]{(-84.07791666666667 + 84.41375) / w, (36.73291666666667 - 36.44625) / h, 0},
                tags.numbers(MODEL_PIXEL_SCALE), 1e-15);
        assertEquals(2, tags.geoKey(GeoKeys.GT_MODEL_TYPE)); // geographic
        assertEquals(4326, tags.geoKey(GeoKeys.GEOGRAPHIC_TYPE));
        assertEquals(9102, tags.geoKey(GeoKeys.GEOG_ANGULAR_UNITS)); // degree
        assertEquals("nan", tags.text(GDAL_NODATA));
    }

    @Test
    void rgbaGeoTiffHasFourBandsWithUnassociatedAlpha() throws IOException {
        int[] argb = new int[41 * 17];
        Random random = new Random(3);
        for (int i = 0; i < argb.length; i++) {
            argb[i] = i % 5 == 0 ? 0 : random.nextInt() | 0x01000000; // transparent no-data, else any alpha > 0
        }
        Path file = dir.resolve("relief.tif");
        ImageOutput.writeRgba(file, argb, 41, 17, null, WriteOptions.defaults());
        BufferedImage back = TiffTags.image(file);
        assertFalse(back.isAlphaPremultiplied());
        assertArrayEquals(argb, back.getRGB(0, 0, 41, 17, null, 0, 41));
        TiffTags tags = TiffTags.read(file);
        assertEquals(4, tags.number(SAMPLES_PER_PIXEL));
        assertEquals(2, tags.number(EXTRA_SAMPLES)); // unassociated alpha
        assertEquals(2, tags.number(PHOTOMETRIC)); // RGB
        assertFalse(tags.has(MODEL_PIXEL_SCALE), "no georeferencing was given");
        assertFalse(tags.has(GeoKeys.TAG_GEO_KEY_DIRECTORY));
    }

    @ParameterizedTest(name = "{0}×{1}")
    @CsvSource({"1, 1", "1, 301", "301, 1", "3, 2"})
    void oddSizesRoundTrip(int width, int height) throws IOException {
        byte[] gray = new byte[width * height];
        new Random(width + 7L * height).nextBytes(gray);
        GeoReference geo = new GeoReference(0, 10, 5, 0, CrsInfo.UNKNOWN);
        Path file = dir.resolve("odd.tif");
        WriteResult result = ImageOutput.writeGray(file, gray, width, height, geo, WriteOptions.defaults());
        assertTrue(result.notices().get(0).contains("no CRS"), result.notices().toString());
        int[] samples = TiffTags.raster(file).getSamples(0, 0, width, height, 0, (int[]) null);
        for (int i = 0; i < gray.length; i++) {
            assertEquals(gray[i] & 0xFF, samples[i]);
        }
        TiffTags tags = TiffTags.read(file);
        assertArrayEquals(new double[]{5.0 / width, 10.0 / height, 0}, tags.numbers(MODEL_PIXEL_SCALE), 1e-12);
        assertEquals(1, tags.geoKey(GeoKeys.GT_RASTER_TYPE));
        assertEquals(1, tags.numbers(GeoKeys.TAG_GEO_KEY_DIRECTORY)[3], "only the raster type key");
        assertFalse(tags.has(GDAL_NODATA));
    }

    @Test
    void userDefinedCrsKeepsItsNameInTheAsciiParams() throws IOException {
        GeoReference geo = new GeoReference(100, 200, 160, 170, CrsInfo.projected("Local grid", null, 0.3048, null));
        Path file = dir.resolve("local.tif");
        WriteResult result = ImageOutput.writeGray(file, new byte[6], 3, 2, geo, WriteOptions.defaults());
        assertTrue(result.notices().get(0).contains("without an EPSG code"), result.notices().toString());
        TiffTags tags = TiffTags.read(file);
        assertEquals(32767, tags.geoKey(GeoKeys.PROJECTED_CS_TYPE));
        assertEquals(9002, tags.geoKey(GeoKeys.PROJ_LINEAR_UNITS));
        assertEquals("Local grid|", tags.text(GeoKeys.TAG_GEO_ASCII_PARAMS));
    }

    /** Noise does not compress: Deflate output is larger than the strip (the JDK TIFF writer truncates it). */
    @Test
    void incompressibleMultiStripDataRoundTrips() throws IOException {
        int w = 300;
        int h = 200; // 240 000 bytes of RGBA or float: four strips of about 64 KiB
        Random random = new Random(4);
        int[] argb = new int[w * h];
        float[] values = new float[w * h];
        for (int i = 0; i < argb.length; i++) {
            argb[i] = random.nextInt();
            values[i] = Float.intBitsToFloat(random.nextInt());
        }
        Path rgba = dir.resolve("noise.tif");
        ImageOutput.writeRgba(rgba, argb, w, h, null, WriteOptions.defaults());
        assertArrayEquals(argb, TiffTags.image(rgba).getRGB(0, 0, w, h, null, 0, w));
        assertTrue(TiffTags.read(rgba).numbers(279).length > 1, "several strips");

        Path flt = dir.resolve("noise32.tif");
        ImageOutput.writeFloat(flt, values, w, h, null, WriteOptions.defaults());
        float[] read = TiffTags.raster(flt).getSamples(0, 0, w, h, 0, (float[]) null);
        for (int i = 0; i < values.length; i++) {
            assertEquals(Float.floatToRawIntBits(values[i]), Float.floatToRawIntBits(read[i]), "pixel " + i);
        }
    }

    /**
     * Strips compressed on all processors make the same file, byte for byte, as strips compressed one after the
     * other: more strips than one parallel batch, of relief (the predictor's case), noise and a partial last strip.
     */
    @Test
    void parallelAndSequentialCompressionWriteTheSameFile() throws IOException {
        int w = 1000;
        int h = 4000 + 37;   // about 60 strips of 65 rows
        byte[] gray = new byte[w * h];
        Random random = new Random(5);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                gray[y * w + x] = y < h / 2 ? (byte) (128 + 100 * Math.sin(x * 0.01) * Math.cos(y * 0.013))
                        : (byte) random.nextInt();
            }
        }
        GeoReference geo = GeoReference.of(TestDems.load(TestDems.BIG_TUJUNGA).geometry());
        Path parallel = dir.resolve("parallel.tif");
        Path sequential = dir.resolve("sequential.tif");
        ImageOutput.writeGray(parallel, gray, w, h, geo, WriteOptions.defaults().withParallelCompression(true));
        ImageOutput.writeGray(sequential, gray, w, h, geo, WriteOptions.defaults().withParallelCompression(false));
        assertTrue(TiffTags.read(parallel).numbers(279).length > 8 * Runtime.getRuntime().availableProcessors(),
                "more strips than one batch");
        assertArrayEquals(java.nio.file.Files.readAllBytes(sequential), java.nio.file.Files.readAllBytes(parallel));
        byte[] read = new byte[w * h];
        TiffTags.raster(parallel).getDataElements(0, 0, w, h, read);
        assertArrayEquals(gray, read);
    }

    /** TIFF 6.0 section 2: IFD and out-of-line values on word boundaries, entries sorted by tag. */
    @Test
    void fileStructureFollowsTheBaselineRules() throws IOException {
        GeoReference geo = new GeoReference(0, 1, 1, 0, CrsInfo.projected("odd name", null, 2.5, null));
        Path file = dir.resolve("layout.tif");
        ImageOutput.writeGray(file, new byte[3 * 5], 3, 5, geo, WriteOptions.defaults().withNoData(7));
        java.nio.ByteBuffer b = java.nio.ByteBuffer.wrap(java.nio.file.Files.readAllBytes(file))
                .order(java.nio.ByteOrder.LITTLE_ENDIAN);
        assertEquals('I', b.get(0));
        assertEquals('I', b.get(1));
        assertEquals(42, b.getShort(2));
        int ifd = b.getInt(4);
        assertEquals(0, ifd % 2);
        int n = b.getShort(ifd);
        int[] typeSizes = {0, 1, 1, 2, 4, 8, 1, 1, 2, 4, 8, 4, 8};
        int previous = -1;
        for (int i = 0; i < n; i++) {
            int at = ifd + 2 + 12 * i;
            int tag = b.getShort(at) & 0xFFFF;
            assertTrue(tag > previous, "tags ascending");
            previous = tag;
            long bytes = (long) typeSizes[b.getShort(at + 2)] * b.getInt(at + 4);
            if (bytes > 4) {
                int offset = b.getInt(at + 8);
                assertEquals(0, offset % 2, "value of tag " + tag + " word-aligned");
                assertTrue(offset + bytes <= b.capacity(), "value of tag " + tag + " inside the file");
            }
        }
        assertEquals(0, b.getInt(ifd + 2 + 12 * n), "a single IFD");
        assertEquals("7", TiffTags.read(file).text(GDAL_NODATA));
    }

    /**
     * Each strip is one zlib stream whose header says the fastest level (RFC 1950 FLEVEL 0, what zlib writes for level
     * 1; its default, 6, writes 2) and that inflates to the strip's rows with the predictor undone.
     */
    @Test
    void stripsAreZlibStreamsOfTheFastestLevel() throws Exception {
        int w = 300;
        int h = 700;
        byte[] gray = new byte[w * h];
        Random random = new Random(5);
        for (int i = 0; i < gray.length; i++) {
            gray[i] = (byte) (i % w < 150 ? 0 : 255 - random.nextInt(3)); // a mask-like half and a noisy half
        }
        Path file = dir.resolve("level.tif");
        ImageOutput.writeGray(file, gray, w, h, null, WriteOptions.defaults());
        byte[] all = java.nio.file.Files.readAllBytes(file);
        TiffTags tags = TiffTags.read(file);
        double[] offsets = tags.numbers(273);
        double[] counts = tags.numbers(279);
        int rowsPerStrip = (int) tags.numbers(278)[0];
        assertTrue(offsets.length > 1, "several strips");
        for (int s = 0; s < offsets.length; s++) {
            int at = (int) offsets[s];
            assertEquals(0x78, all[at] & 0xFF, "strip " + s + ": deflate, 32 KiB window");
            assertEquals(0, (all[at + 1] & 0xFF) >> 6, "strip " + s + ": FLEVEL of the fastest level");
            java.util.zip.Inflater inflater = new java.util.zip.Inflater();
            inflater.setInput(all, at, (int) counts[s]);
            int rows = Math.min(rowsPerStrip, h - s * rowsPerStrip);
            byte[] strip = new byte[rows * w];
            assertEquals(strip.length, inflater.inflate(strip));
            assertTrue(inflater.finished(), "strip " + s + " is one whole stream");
            inflater.end();
            for (int r = 0; r < rows; r++) {
                for (int x = 1; x < w; x++) { // undo the horizontal predictor
                    strip[r * w + x] += strip[r * w + x - 1];
                }
            }
            assertArrayEquals(java.util.Arrays.copyOfRange(gray, s * rowsPerStrip * w, s * rowsPerStrip * w
                    + strip.length), strip, "strip " + s);
        }
    }

    @Test
    void noDataTextIsWhatGdalParses() {
        assertEquals("0", GeoTiffTags.noDataText(0));
        assertEquals("-9999", GeoTiffTags.noDataText(-9999));
        assertEquals("nan", GeoTiffTags.noDataText(Double.NaN));
        assertEquals("0.5", GeoTiffTags.noDataText(0.5));
        assertEquals(-3.4028235E38f, Float.parseFloat(GeoTiffTags.noDataText(-3.4028234663852886E38)));
    }
}
