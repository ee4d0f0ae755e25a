package io.github.jdem846.io.geotiff;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.SampleDecoder;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.testing.FuzzInputs;
import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Fuzz tests of the GeoTIFF reader: the whole file (image directory, {@link TiffFields}, {@link GeoTiffTags},
 * GeoKeys, strips and tiles through {@link GeoTiffSource}), the GeoKey directory alone ({@link GeoKeyReader},
 * {@link GeoTiffCrs}), {@link TiffLzw} and {@link PredictorUndo}. The normal test run replays the inputs in
 * {@code src/test/resources/io/github/jdem846/io/geotiff/GeoTiffFuzzTestInputs/<method>/}; {@code -Pfuzz} fuzzes
 * (docs/reliability.md).
 */
// a hang: more than 10 s for one input (Jazzer passes it to libFuzzer as -timeout when fuzzing)
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class GeoTiffFuzzTest {

    /**
     * A GeoTIFF opens and its cells decode, or it is refused with a DemFormatException naming it. The source is
     * used directly (two to three times as many executions per second as through {@link DemReader}, whose own
     * checks {@code FuzzReproducerTest} and {@code ReaderLimitsTest} exercise): at most {@link #MAX_CELLS} cells
     * are read, the top rows and the bottom rows, so that a huge declared grid still has its blocks decoded.
     */
    @FuzzTest
    void geoTiff(byte[] data) throws Exception {
        Path tif = FuzzInputs.write("fuzz_geotiff.tif", data);
        FuzzInputs.readsOrRefuses(tif, data.length, () -> {
            try (RasterSource source = GeoTiffSource.open(tif)) {
                int width = (int) Math.min(source.info().width(), MAX_CELLS);
                int height = source.info().height();
                int rows = (int) Math.max(1, Math.min(height, MAX_CELLS / 2 / width));
                float[] cells = new float[width * rows];
                source.readRows(0, 0, width, rows, cells);
                source.readRows(0, height - rows, width, rows, cells);
            }
        });
    }

    /** The most cells the geoTiff target reads of one input. */
    private static final long MAX_CELLS = 1 << 20;

    /**
     * A GeoKey directory (its SHORT values, the double and ASCII parameters) parses or is refused with the
     * documented IllegalArgumentException, and every parsed directory resolves to a CRS (perhaps unknown).
     */
    @FuzzTest
    void geoKeys(FuzzedDataProvider in) {
        int keys = in.consumeInt(0, 40);
        long[] dir = new long[in.consumeInt(0, 4 + 4 * keys)];
        for (int i = 0; i < dir.length; i++) {
            dir[i] = i == 3 ? keys : in.consumeInt(0, 0xFFFF);
        }
        double[] doubles = in.consumeBoolean() ? null : new double[in.consumeInt(0, 16)];
        if (doubles != null) {
            for (int i = 0; i < doubles.length; i++) {
                doubles[i] = in.consumeDouble();
            }
        }
        String ascii = in.consumeBoolean() ? null : in.consumeRemainingAsString();
        GeoKeyReader reader;
        try {
            reader = GeoKeyReader.parse(dir, doubles, ascii);
        } catch (IllegalArgumentException e) {
            if (!e.getStackTrace()[0].getClassName().equals(GeoKeyReader.class.getName())) {
                throw e; // not the parser's own refusal of a malformed directory
            }
            return;
        }
        List<String> notices = new ArrayList<>();
        if (GeoTiffCrs.resolve(reader, notices) == null) {
            throw new AssertionError("no CRS, not even the unknown one");
        }
    }

    /** LZW data decompress into at most the room given, or fail with the documented IOException. */
    @FuzzTest
    void tiffLzw(FuzzedDataProvider in) {
        byte[] dst = new byte[in.consumeInt(0, 1 << 16)];
        byte[] src = in.consumeRemainingAsBytes();
        try {
            int n = TiffLzw.decode(src, src.length, dst);
            if (n < 0 || n > dst.length) {
                throw new AssertionError(n + " bytes decoded into " + dst.length);
            }
        } catch (IOException e) {
            // corrupt data, documented
        }
    }

    /** Any predictor, sample type and byte order over any row bytes: samples out, never an exception. */
    @FuzzTest
    void predictorUndo(FuzzedDataProvider in) {
        SampleType[] types = {SampleType.INT8, SampleType.UINT8, SampleType.INT16, SampleType.UINT16,
                SampleType.INT32, SampleType.UINT32, SampleType.FLOAT32, SampleType.FLOAT64};
        SampleType type = in.pickValue(types);
        boolean floats = type == SampleType.FLOAT32 || type == SampleType.FLOAT64;
        int predictor = in.pickValue(floats ? new int[] {1, 3} : new int[] {1, 2});
        ByteOrder order = in.consumeBoolean() ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN;
        int samples = in.consumeInt(1, 512);
        int off = in.consumeInt(0, 64);
        int from = in.consumeInt(0, samples - 1);
        int n = in.consumeInt(0, samples - from);
        byte[] raw = new byte[off + samples * type.bytes()];
        byte[] given = in.consumeRemainingAsBytes();
        System.arraycopy(given, 0, raw, 0, Math.min(given.length, raw.length));
        float[] dst = new float[n + 3];
        PredictorUndo.row(raw, off, samples, predictor, type, order, from, n, dst, 3, new SampleDecoder());
    }
}
