package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemReader;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Bad input gives one clear line naming the file and the problem, exit status 1 (2 for bad usage), and no stack
 * trace unless {@code --verbose}.
 */
class BadInputTest {

    private static final Path V04 =
            Path.of("testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif");

    @TempDir
    Path tmp;

    /** Runs {@code info FILE}, expects exit 1 and a one-line message naming the file and containing the parts. */
    private static void assertRefused(Path file, String... parts) {
        assertRefusedNaming(file, file.getFileName().toString(), parts);
    }

    /** As above, where the message names {@code namedFile} (e.g. the .hdr at fault). */
    private static void assertRefusedNaming(Path file, String namedFile, String... parts) {
        CliRun run = CliRun.of("info", file.toString());
        assertEquals(1, run.exitCode(), run.out() + run.err());
        String err = run.err().strip();
        assertTrue(err.startsWith("jdem846: "), err);
        assertTrue(err.contains(namedFile), "names " + namedFile + ": " + err);
        for (String p : parts) {
            assertTrue(err.contains(p), "missing '" + p + "' in: " + err);
        }
        assertFalse(err.contains("\tat ") || err.contains("Exception"), "no stack trace: " + err);
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertEquals("", run.out());
    }

    private Path gridFloat(String name, String header, int floats) throws IOException {
        Path flt = tmp.resolve(name + ".flt");
        Files.write(flt, new byte[floats * 4]);
        Files.writeString(tmp.resolve(name + ".hdr"), header);
        return flt;
    }

    private static final String GOOD_HEADER =
            "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\nbyteorder LSBFIRST\n";

    @Test
    void missingFile() {
        assertRefused(tmp.resolve("nothere.tif"), "no such file");
    }

    @Test
    void missingHdr() throws IOException {
        Path flt = tmp.resolve("lonely.flt");
        Files.write(flt, new byte[24]);
        assertRefusedNaming(flt, "lonely.hdr", "header file not found", "GridFloat lonely.flt needs");
    }

    @Test
    void headerKeyMissing() throws IOException {
        assertRefusedNaming(gridFloat("m1", GOOD_HEADER.replace("ncols 3\n", ""), 6), "m1.hdr", "'ncols' is missing");
        assertRefusedNaming(gridFloat("m2", GOOD_HEADER.replace("cellsize 1\n", ""), 6), "m2.hdr",
                "'cellsize' is missing");
        assertRefusedNaming(gridFloat("m3", GOOD_HEADER.replace("yllcorner 0\n", ""), 6), "m3.hdr",
                "'yllcorner' is missing");
    }

    @Test
    void headerKeyGarbled() throws IOException {
        assertRefusedNaming(gridFloat("g1", GOOD_HEADER.replace("ncols 3", "ncols three"), 6), "g1.hdr",
                "'ncols' is 'three', not a whole number");
        assertRefusedNaming(gridFloat("g2", GOOD_HEADER.replace("cellsize 1", "cellsize 1,5"), 6), "g2.hdr",
                "'cellsize' is '1,5', not a number");
        assertRefusedNaming(gridFloat("g3", GOOD_HEADER.replace("LSBFIRST", "SIDEWAYS"), 6), "g3.hdr",
                "'byteorder' is 'SIDEWAYS'");
    }

    @Test
    void headerKeyNegative() throws IOException {
        assertRefusedNaming(gridFloat("n1", GOOD_HEADER.replace("nrows 2", "nrows -2"), 6), "n1.hdr", "'nrows' is -2",
                "from 1 to");
        assertRefusedNaming(gridFloat("n2", GOOD_HEADER.replace("cellsize 1", "cellsize -30"), 6), "n2.hdr",
                "'cellsize' is -30", "positive");
    }

    @Test
    void fltSizeDoesNotMatchTheHeader() throws IOException {
        assertRefused(gridFloat("a", GOOD_HEADER, 5), "is 20 bytes", "3 × 2 × 4 = 24 bytes");
    }

    @Test
    void truncatedTiff() throws IOException {
        Path t = tmp.resolve("truncated.tif");
        byte[] all = Files.readAllBytes(V04);
        Files.write(t, java.util.Arrays.copyOf(all, all.length / 2));
        assertRefused(t, "truncated TIFF", "but the file has " + all.length / 2 + " bytes");
    }

    @Test
    void tiffCutInsideItsHeader() throws IOException {
        Path t = tmp.resolve("stub.tif");
        Files.write(t, java.util.Arrays.copyOf(Files.readAllBytes(V04), 12));
        assertRefused(t, "truncated or corrupt");
    }

    @Test
    void corruptTiffData() throws IOException {
        Path t = tmp.resolve("corrupt.tif");
        byte[] all = Files.readAllBytes(V04);
        // Overwrite compressed tile data (the strip/tile data follow the IFD, which GDAL writes first).
        for (int i = 20_000; i < 60_000; i++) {
            all[i] = (byte) (i * 31);
        }
        Files.write(t, all);
        assertRefused(t, "corrupt");
    }

    @Test
    void unsupportedSampleFormat() {
        assertRefused(Path.of("testdata/formats/volcano_cint16.tif"), "unsupported sample format",
                "complex integer");
    }

    @Test
    void unsupportedCompressionIsNamedWithARemedy() {
        assertRefused(Path.of("testdata/formats/volcano_zstd.tif"), "ZSTD compression", "not supported",
                "COMPRESS=DEFLATE", "PREDICTOR=2");
    }

    @Test
    void theRemedyForFloatingPointSamplesUsesTheFloatingPointPredictor() throws IOException {
        // the int16 ZSTD file declared as float32 (BitsPerSample 32, SampleFormat 3): refused before any pixel
        // is read, with the predictor that suits floating-point data
        byte[] b = Files.readAllBytes(Path.of("testdata/formats/volcano_zstd.tif"));
        setShortEntry(b, 258, 32);
        setShortEntry(b, 339, 3);
        Path f = tmp.resolve("float_zstd.tif");
        Files.write(f, b);
        assertRefused(f, "ZSTD compression", "PREDICTOR=3");
    }

    /** Sets the inline SHORT value of tag {@code tag} in the first IFD of a little-endian classic TIFF. */
    private static void setShortEntry(byte[] tiff, int tag, int value) {
        ByteBuffer bb = ByteBuffer.wrap(tiff).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals('I', (char) tiff[0], "a little-endian TIFF");
        int ifd = bb.getInt(4);
        int n = bb.getShort(ifd) & 0xFFFF;
        for (int i = 0; i < n; i++) {
            int at = ifd + 2 + 12 * i;
            if ((bb.getShort(at) & 0xFFFF) == tag) {
                assertEquals(1, bb.getInt(at + 4), "one value");
                bb.putShort(at + 8, (short) value);
                return;
            }
        }
        throw new AssertionError("no tag " + tag);
    }

    @Test
    void rotatedGrid() {
        assertRefused(Path.of("testdata/formats/volcano_rotated.tif"), "rotated or sheared");
    }

    @Test
    void emptyFile() throws IOException {
        Path e = Files.createFile(tmp.resolve("empty.tif"));
        assertRefused(e, "is empty (0 bytes)");
    }

    @Test
    void directory() throws IOException {
        Path d = Files.createDirectory(tmp.resolve("dem.tif"));
        assertRefused(d, "is a directory");
    }

    @Test
    void notADem() throws IOException {
        Path p = tmp.resolve("notes.txt");
        Files.writeString(p, "hello");
        assertRefused(p, "not a DEM format");
        Path tif = tmp.resolve("fake.tif");
        Files.writeString(tif, "hello");
        assertRefused(tif, "not a TIFF");
    }

    @Test
    void verboseAddsTheStackTrace() throws IOException {
        Path flt = gridFloat("v", GOOD_HEADER, 5);
        CliRun run = CliRun.of("info", "--verbose", flt.toString());
        assertEquals(1, run.exitCode());
        assertTrue(run.err().contains("DemFormatException") && run.err().contains("\tat "), run.err());
    }

    @Test
    void badUsageExitsWith2() {
        CliRun run = CliRun.of("info", "--no-such-option");
        assertEquals(2, run.exitCode());
        assertTrue(run.err().contains("--no-such-option"), run.err());
        // several files are a mosaic now; a pattern that matches nothing is bad usage
        assertEquals(2, CliRun.of("info", "no/such/dir/*.tif").exitCode());
    }

    /**
     * A minimal classic little-endian TIFF header for a {@code side × side} Int16 image with one strip of 2 bytes:
     * the pixels are never decoded.
     */
    private Path hugeTiff(int side) throws IOException {
        short[][] entries = {};
        ByteBuffer b = ByteBuffer.allocate(8 + 2 + 10 * 12 + 4 + 2).order(ByteOrder.LITTLE_ENDIAN);
        b.put((byte) 'I').put((byte) 'I').putShort((short) 42).putInt(8);
        int[][] tags = { // tag, type (3 SHORT, 4 LONG), value
            {256, 4, side}, {257, 4, side}, {258, 3, 16}, {259, 3, 1}, {262, 3, 1},
            {273, 4, 8 + 2 + 10 * 12 + 4}, {277, 3, 1}, {278, 4, side}, {279, 4, 2}, {339, 3, 2}};
        b.putShort((short) tags.length);
        for (int[] t : tags) {
            b.putShort((short) t[0]).putShort((short) t[1]).putInt(1);
            if (t[1] == 3) {
                b.putShort((short) t[2]).putShort((short) 0);
            } else {
                b.putInt(t[2]);
            }
        }
        b.putInt(0).putShort((short) 0);
        Path p = tmp.resolve("huge" + side + ".tif");
        Files.write(p, b.array());
        assertEquals(0, entries.length);
        return p;
    }

    @Test
    void gridLargerThanTheHeapIsRefusedBeforeAllocating() throws IOException {
        long max = Runtime.getRuntime().maxMemory();
        int side = (int) Math.min(46_000, Math.ceil(Math.sqrt(2.0 * max / 4)));
        Path tif = hugeTiff(side);
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.read(tif));
        String m = e.getMessage();
        assertTrue(m.contains(tif.toString()), m);
        assertTrue(m.contains(side + " × " + side) && m.contains("GiB") && m.contains("Runtime.maxMemory()"), m);
        // The inspection of the same file works: only the header is read.
        assertEquals(side, DemReader.inspect(tif).width());
    }

    @Test
    void gridLargerThanAJavaArrayIsRefused() throws IOException {
        Path tif = hugeTiff(100_000);
        DemFormatException e = assertThrows(DemFormatException.class, () -> DemReader.read(tif));
        assertTrue(e.getMessage().contains("37.3 GiB"), e.getMessage()); // 1e10 cells × 4 bytes
        assertTrue(e.getMessage().contains("more than one Java array can hold"), e.getMessage());
    }

    @Test
    void aHdrGivenByMistakeReadsItsFlt() throws IOException {
        Path dir = tmp.resolve("d");
        Files.createDirectory(dir);
        for (String ext : new String[] {".flt", ".hdr", ".prj"}) {
            Files.copy(Path.of("testdata/dem/luxembourg_srtm30s_wgs84" + ext), dir.resolve("lux" + ext),
                    StandardCopyOption.REPLACE_EXISTING);
        }
        CliRun run = CliRun.of("info", "--json", dir.resolve("lux.hdr").toString());
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().contains("\"nodataCount\": 3942"), run.out());
    }
}
