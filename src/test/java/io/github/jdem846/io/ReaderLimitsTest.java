package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.TiffPatch;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The readers' limits, one row per absurd input made from a real testdata file by patching bytes: sizes up to
 * 2³¹−1 and 10⁹ × 10⁹, strip counts, offsets and byte counts past the end of the file, Deflate strips overwritten,
 * cut short or inflating beyond their declared size, 2³¹−1 samples per pixel, NaN, zero, negative and infinite cell sizes and origins,
 * headers contradicting the data file's length, a VRT of 2³¹−1 columns, an endless device and a directory. Each is
 * refused by read, inspect and statistics alike (inspect where the header alone is at fault) with a
 * {@link DemFormatException} naming the file and the problem, before anything of the declared size is allocated
 * (the JVM's 2 GiB heap could not hold it) and without hanging (the timeout). FIFOs and other devices:
 * {@code NonRegularFileTest}; synthetic TIFF structures: {@code TiffStructureTest}, {@code HugeSizeTest}.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class ReaderLimitsTest {

    private static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif");
    private static final Path VOLCANO_ASC = Path.of("testdata/formats/volcano.asc");
    private static final Path LUXEMBOURG = Path.of("testdata/dem/luxembourg_srtm30s_wgs84");
    private static final Path VOLCANO_BIL = Path.of("testdata/formats/volcano");

    // TIFF tags
    private static final int WIDTH = 256;
    private static final int HEIGHT = 257;
    private static final int STRIP_OFFSETS = 273;
    private static final int SAMPLES_PER_PIXEL = 277;
    private static final int ROWS_PER_STRIP = 278;
    private static final int STRIP_BYTE_COUNTS = 279;
    private static final int PIXEL_SCALE = 33550;
    private static final int TIEPOINT = 33922;

    @TempDir
    Path tmp;

    /** How a case makes its file in the temporary directory. */
    @FunctionalInterface
    interface Maker {
        Path make(Path dir) throws IOException;
    }

    /** What a case is refused by: the header alone (also inspect) or only once the data are read. */
    enum Stage { HEADER, DATA }

    private static Arguments row(String name, Stage stage, Maker maker, String... expected) {
        return Arguments.of(name, stage, maker, expected);
    }

    /** The jacksboro GeoTIFF (403 × 344 int16, Deflate with predictor 2, 35 strips of 10 rows), patched. */
    private static Maker tiff(String name, TiffEdit edit) {
        return dir -> {
            TiffPatch p = TiffPatch.of(JACKSBORO);
            edit.apply(p, Files.size(JACKSBORO));
            return p.write(dir.resolve(name + ".tif"));
        };
    }

    @FunctionalInterface
    interface TiffEdit {
        void apply(TiffPatch p, long fileLength);
    }

    /** testdata's volcano.asc with header lines replaced ("key value"). */
    private static Maker ascii(String name, String... keyValues) {
        return dir -> {
            String text = Files.readString(VOLCANO_ASC, StandardCharsets.US_ASCII);
            return Files.writeString(dir.resolve(name + ".asc"), withHeader(text, keyValues));
        };
    }

    /** An ESRI data file and its .hdr (and .prj) copied, the .hdr's lines replaced; the data file returned. */
    private static Maker esri(Path base, String dataExt, String name, String... keyValues) {
        return dir -> {
            Path data = dir.resolve(name + "." + dataExt);
            Files.copy(Path.of(base + "." + dataExt), data);
            String hdr = Files.readString(Path.of(base + ".hdr"), StandardCharsets.US_ASCII);
            Files.writeString(dir.resolve(name + ".hdr"), withHeader(hdr, keyValues));
            Path prj = Path.of(base + ".prj");
            if (Files.exists(prj)) {
                Files.copy(prj, dir.resolve(name + ".prj"));
            }
            return data;
        };
    }

    /** The lines whose first word is one of the keys (case-insensitive) replaced by "key value". */
    private static String withHeader(String text, String... keyValues) {
        StringBuilder out = new StringBuilder();
        for (String line : text.split("\n", -1)) {
            String first = line.strip().split("\\s+", 2)[0];
            String replaced = line;
            for (String kv : keyValues) {
                String key = kv.split(" ", 2)[0];
                if (first.equalsIgnoreCase(key)) {
                    replaced = kv;
                }
            }
            out.append(replaced).append('\n');
        }
        return out.substring(0, out.length() - 1);
    }

    static Stream<Arguments> matrix() {
        long maxInt = Integer.MAX_VALUE;
        return Stream.of(
                // GeoTIFF sizes and structure
                row("tiff width 2^31-1", Stage.DATA, tiff("w", (p, n) -> p.set(WIDTH, maxInt))),
                row("tiff height 2^31-1", Stage.HEADER, tiff("h", (p, n) -> p.set(HEIGHT, maxInt))),
                row("tiff 10^9 x 10^9", Stage.HEADER,
                        tiff("g", (p, n) -> p.set(WIDTH, 1_000_000_000L).set(HEIGHT, 1_000_000_000L))),
                row("tiff strip byte count past the end", Stage.HEADER,
                        tiff("c", (p, n) -> p.set(STRIP_BYTE_COUNTS, 3, 1_000_000_000L)),
                        "its strips reach byte 1000013443 but the file has 144376 bytes"),
                row("tiff strip offset past the end", Stage.HEADER,
                        tiff("o", (p, n) -> p.set(STRIP_OFFSETS, 3, n + 1000)), "but the file has 144376 bytes"),
                row("tiff SamplesPerPixel 2^31-1", Stage.HEADER,
                        tiff("spp", (p, n) -> p.set(SAMPLES_PER_PIXEL, maxInt)), "SamplesPerPixel (tag 277)"),
                row("tiff fewer strips than rows need", Stage.HEADER,
                        tiff("r", (p, n) -> p.set(ROWS_PER_STRIP, 1))),
                row("tiff deflate strip inflating beyond its declared size", Stage.DATA,
                        tiff("bomb", (p, n) -> p.set(HEIGHT, 5)), "holds more than the block's"),
                row("tiff deflate strip overwritten with 3000 bytes of 0xff", Stage.DATA,
                        tiff("ff", (p, n) -> p.fill((int) n / 2, 3000, 0xFF)), "Deflate"),
                row("tiff deflate strip cut short", Stage.DATA,
                        tiff("cut", (p, n) -> p.set(STRIP_BYTE_COUNTS, 0, p.get(STRIP_BYTE_COUNTS, 0) / 2)),
                        "Deflate stream"),
                row("tiff cell size NaN", Stage.HEADER, tiff("sn", (p, n) -> p.setDouble(PIXEL_SCALE, 0, Double.NaN))),
                row("tiff cell size 0", Stage.HEADER, tiff("s0", (p, n) -> p.setDouble(PIXEL_SCALE, 1, 0))),
                row("tiff cell size infinite", Stage.HEADER,
                        tiff("si", (p, n) -> p.setDouble(PIXEL_SCALE, 0, Double.POSITIVE_INFINITY))),
                row("tiff origin NaN", Stage.HEADER, tiff("on", (p, n) -> p.setDouble(TIEPOINT, 3, Double.NaN))),
                row("tiff origin infinite", Stage.HEADER,
                        tiff("oi", (p, n) -> p.setDouble(TIEPOINT, 4, Double.NEGATIVE_INFINITY))),
                row("tiff origin 1e308 (extent overflows)", Stage.HEADER,
                        tiff("ob", (p, n) -> p.setDouble(TIEPOINT, 3, 1e308).setDouble(PIXEL_SCALE, 0, 1e308))),
                // ESRI ASCII grid
                row("ascii ncols 2^31-1", Stage.HEADER, ascii("w", "ncols 2147483647"), "promises ncols × nrows"),
                row("ascii 10^9 x 10^9", Stage.HEADER, ascii("g", "ncols 1000000000", "nrows 1000000000"),
                        "promises ncols × nrows = 1000000000 × 1000000000"),
                row("ascii more rows than the data", Stage.DATA, ascii("r", "nrows 88")),
                row("ascii cellsize NaN", Stage.HEADER, ascii("sn", "cellsize NaN"), "cellsize"),
                row("ascii cellsize 0", Stage.HEADER, ascii("s0", "cellsize 0"), "cellsize"),
                row("ascii cellsize negative", Stage.HEADER, ascii("sm", "cellsize -10"), "cellsize"),
                row("ascii cellsize infinite", Stage.HEADER, ascii("si", "cellsize Infinity"), "cellsize"),
                row("ascii yllcorner 1e308", Stage.HEADER, ascii("yb", "yllcorner 1e308")),
                row("ascii xllcorner NaN", Stage.HEADER, ascii("xn", "xllcorner NaN"), "xllcorner"),
                // GridFloat and BIL: the header against the data file's length
                row("gridfloat 10^9 x 10^9", Stage.HEADER,
                        esri(LUXEMBOURG, "flt", "g", "ncols 1000000000", "nrows 1000000000")),
                row("gridfloat header contradicting the file length", Stage.HEADER,
                        esri(LUXEMBOURG, "flt", "n", "nrows 91")),
                row("gridfloat cellsize negative", Stage.HEADER,
                        esri(LUXEMBOURG, "flt", "sm", "cellsize -0.008333333333333337"), "cellsize"),
                row("gridfloat yllcorner 1e308", Stage.HEADER, esri(LUXEMBOURG, "flt", "yb", "yllcorner 1e308")),
                row("bil rows 10^9", Stage.HEADER, esri(VOLCANO_BIL, "bil", "r", "NROWS 1000000000")),
                row("bil ncols 2^31-1", Stage.HEADER, esri(VOLCANO_BIL, "bil", "w", "NCOLS 2147483647")),
                row("bil xdim NaN", Stage.HEADER, esri(VOLCANO_BIL, "bil", "xn", "XDIM NaN")),
                // a VRT of absurd size
                row("vrt 2^31-1 columns", Stage.HEADER, dir -> Files.writeString(dir.resolve("huge.vrt"),
                        "<VRTDataset rasterXSize=\"2147483647\" rasterYSize=\"2147483647\"><VRTRasterBand"
                                + " dataType=\"Float32\" band=\"1\"/></VRTDataset>")),
                // an endless input and a directory
                row("endless device named .asc", Stage.HEADER,
                        dir -> Files.createSymbolicLink(dir.resolve("zero.asc"), Path.of("/dev/zero")),
                        "not a regular file"),
                row("directory named .tif", Stage.HEADER, dir -> Files.createDirectory(dir.resolve("dir.tif"))));
    }

    @FunctionalInterface
    private interface Read {
        Object apply(Path file) throws IOException;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("matrix")
    void absurdInputIsRefusedNamingTheFile(String name, Stage stage, Maker maker, String[] expected)
            throws IOException {
        Path file = maker.make(tmp);
        Read[] reads = stage == Stage.HEADER
                ? new Read[] {DemReader::read, DemReader::inspect, DemReader::statistics}
                : new Read[] {DemReader::read, DemReader::statistics};
        for (Read read : reads) {
            DemFormatException e = assertThrows(DemFormatException.class, () -> read.apply(file), name);
            String m = e.getMessage();
            String base = file.toString().replaceFirst("\\.[^./]*$", "");
            assertTrue(m.startsWith(file + ": ") || m.startsWith(base + "."), name + ": " + m);
            String problem = m.substring(m.indexOf(": ") + 2);
            assertTrue(problem.length() > 10 && !problem.toLowerCase(Locale.ROOT).contains("exception"),
                    name + ": " + m);
            for (String part : expected) {
                assertTrue(m.contains(part), name + ": '" + part + "' missing in: " + m);
            }
        }
        if (Files.isSymbolicLink(file)) {
            Files.delete(file); // the link, not /dev/zero; JUnit would warn about it
        }
    }

    @Test
    void aDirectoryChainLoopingBackToTheFirstStillReadsTheFirstImage() throws IOException {
        TiffPatch p = TiffPatch.of(JACKSBORO);
        Path loop = p.nextDirectory(p.firstDirectory()).write(tmp.resolve("loop.tif"));
        Dem original = DemReader.read(JACKSBORO);
        Dem looped = DemReader.read(loop);
        assertArrayEquals(original.backingArray(), looped.backingArray());
    }

    @Test
    void theUnpatchedFilesRead() throws IOException {
        for (Path file : new Path[] {JACKSBORO, VOLCANO_ASC, Path.of(LUXEMBOURG + ".flt"),
                Path.of(VOLCANO_BIL + ".bil")}) {
            assertTrue(DemReader.read(file).width() > 0, file.toString());
        }
    }
}
