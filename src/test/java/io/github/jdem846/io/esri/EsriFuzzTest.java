package io.github.jdem846.io.esri;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.testing.FuzzInputs;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Fuzz tests of the ESRI readers: an ASCII grid ({@link EsriAsciiSource}, its head parsed by {@link EsriHeader}),
 * the {@code .hdr} of a GridFloat and of a BIL file (with real data next to it), the {@code .prj} next to a grid
 * ({@link SidecarCrs}: ESRI or OGC WKT, or ArcInfo's keyword format), and {@link ArcInfoPrj} alone. The normal
 * test run replays the inputs in {@code src/test/resources/io/github/jdem846/io/esri/EsriFuzzTestInputs/<method>/};
 * {@code -Pfuzz} fuzzes (docs/reliability.md).
 */
// a hang: more than 10 s for one input (Jazzer passes it to libFuzzer as -timeout when fuzzing)
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class EsriFuzzTest {

    /**
     * A small real grid for the .prj target: the top-left 20 × 4 cells of testdata's formats/volcano.asc
     * (Maungawhau, 10 m), with its origin moved to their lower-left corner.
     */
    private static final String SMALL_GRID = """
            ncols 20
            nrows 4
            xllcorner 1756944
            yllcorner 5917954
            cellsize 10
            94 94 94 94 94 94 94 94 94 94 94 94 94 94 95 95 95 95 96 96
            94 94 94 94 94 94 94 94 94 94 94 94 95 95 95 95 95 96 96 96
            94 94 94 94 94 94 94 94 94 94 95 95 95 95 95 95 96 96 96 96
            94 94 94 94 94 94 94 94 95 95 95 95 95 95 95 96 96 96 96 97
            """;

    private static final byte[] LUXEMBOURG_FLT = testdata("dem/luxembourg_srtm30s_wgs84.flt");
    private static final byte[] VOLCANO_BIL = testdata("formats/volcano.bil");

    /** An ESRI ASCII grid reads or is refused with a DemFormatException naming it. */
    @FuzzTest
    void esriAscii(byte[] data) throws Exception {
        Path asc = FuzzInputs.write("fuzz_ascii.asc", data);
        FuzzInputs.readsOrRefuses(asc, data.length, () -> readDirectly(EsriAsciiSource.open(asc)));
    }

    /**
     * Reads the top and bottom rows of a source, at most {@link #MAX_CELLS} cells: the reader used directly, at
     * two to three times the executions per second of {@link DemReader#read} (whose own checks
     * {@code FuzzReproducerTest} and {@code ReaderLimitsTest} exercise), still decoding rows of a huge declared
     * grid.
     */
    private static void readDirectly(RasterSource opened) throws IOException {
        try (RasterSource source = opened) {
            int width = (int) Math.min(source.info().width(), MAX_CELLS);
            int height = source.info().height();
            int rows = (int) Math.max(1, Math.min(height, MAX_CELLS / 2 / width));
            float[] cells = new float[width * rows];
            source.readRows(0, 0, width, rows, cells);
            source.readRows(0, height - rows, width, rows, cells);
        }
    }

    /** The most cells a target reads of one input. */
    private static final long MAX_CELLS = 1 << 20;

    /**
     * A GridFloat {@code .hdr} next to real float32 data (testdata's 171 × 50 cells of Luxembourg): reads or is
     * refused naming the .flt or the .hdr.
     */
    @FuzzTest
    void gridFloatHeader(byte[] hdr) throws Exception {
        Path flt = FuzzInputs.write("fuzz_gridfloat.flt", LUXEMBOURG_FLT);
        FuzzInputs.write("fuzz_gridfloat.hdr", hdr);
        FuzzInputs.readsOrRefuses(flt, hdr.length, () -> readDirectly(GridFloatFormat.open(flt)));
    }

    /** A BIL {@code .hdr} next to real int16 data (testdata's volcano.bil): reads or is refused naming either. */
    @FuzzTest
    void bilHeader(byte[] hdr) throws Exception {
        Path bil = FuzzInputs.write("fuzz_bil.bil", VOLCANO_BIL);
        FuzzInputs.write("fuzz_bil.hdr", hdr);
        FuzzInputs.readsOrRefuses(bil, hdr.length, () -> readDirectly(BilFormat.open(bil)));
    }

    /** A {@code .prj} next to a small valid grid: the grid reads (the CRS perhaps unknown) or is refused. */
    @FuzzTest
    void prj(byte[] data) throws Exception {
        Path asc = FuzzInputs.write("fuzz_prj.asc", SMALL_GRID.getBytes(StandardCharsets.US_ASCII));
        FuzzInputs.write("fuzz_prj.prj", data);
        FuzzInputs.readsOrRefuses(asc, data.length, () -> DemReader.read(asc));
    }

    private static byte[] testdata(String file) {
        try {
            return Files.readAllBytes(Path.of("testdata", file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** ArcInfo's keyword {@code .prj}: a CRS or the documented IllegalArgumentException. */
    @FuzzTest
    void arcInfoPrj(byte[] data) {
        String text = new String(data, StandardCharsets.ISO_8859_1);
        if (!ArcInfoPrj.looksLikeOne(text)) {
            return;
        }
        List<String> notices = new ArrayList<>();
        try {
            if (ArcInfoPrj.parse(text, "fuzz.prj", notices) == null) {
                throw new AssertionError("no CRS");
            }
        } catch (IllegalArgumentException e) {
            StackTraceElement top = e.getStackTrace()[0];
            if (!top.getClassName().equals(ArcInfoPrj.class.getName())) {
                throw e; // not the parser's own refusal
            }
        }
    }
}
