package io.github.jdem846.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.testing.SyntheticDems;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The no-data rule: comparison as float32, however a header printed the value. */
class NoDataTest {

    @TempDir
    Path tmp;

    @ParameterizedTest
    @ValueSource(strings = {"-3.4028235e38", "-3.40282e+38", "-3.402823e+38", "-3.4028234663852886e+38",
        "-340282346638528859811704183484516925440"})
    void floatMaxWrittenAnyWayMatchesTheStoredCell(String header) {
        assertTrue(NoData.isNoData(-Float.MAX_VALUE, Double.parseDouble(header)), header);
        assertFalse(NoData.isNoData(Float.MAX_VALUE, Double.parseDouble(header)), "sign matters: " + header);
        assertFalse(NoData.isNoData(-3.0e38f, Double.parseDouble(header)), "a distinct large value: " + header);
    }

    @Test
    void integersAndRoundedHeaderValuesMatchAsFloat32() {
        assertTrue(NoData.isNoData(-32768f, -32768.0));
        assertTrue(NoData.isNoData(-9999f, Double.parseDouble("-9999.000")));
        assertTrue(NoData.isNoData(0.1f, 0.1), "0.1 as float32 equals the cell 0.1f although 0.1 ≠ (double) 0.1f");
        assertFalse(NoData.isNoData(0f, Double.NaN), "no declared value: 0 is an elevation");
        assertTrue(NoData.isNoData(Float.NaN, Double.NaN), "NaN is always no-data");
        assertTrue(NoData.isNoData(Float.NaN, -9999), "NaN is always no-data");
    }

    @Test
    void gridFloatWithARoundedFloatMaxHeaderHasNoDataCells() throws IOException {
        ByteBuffer b = ByteBuffer.allocate(16).order(ByteOrder.LITTLE_ENDIAN);
        b.putFloat(-Float.MAX_VALUE).putFloat(12.5f).putFloat(-Float.MAX_VALUE).putFloat(0f);
        Files.write(tmp.resolve("m.flt"), b.array());
        Files.writeString(tmp.resolve("m.hdr"), "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
                + "NODATA_value -3.40282e+38\nbyteorder LSBFIRST\n");
        Dem dem = DemReader.read(tmp.resolve("m.flt"));
        assertEquals(2, dem.statistics().noDataCount());
        assertEquals(0, dem.statistics().min(), "0 is sea level, not no-data");
        assertEquals(12.5, dem.statistics().max());
    }

    @Test
    void allFiniteIsKnownOnlyOnceTheStatisticsAreAndCountEveryCell() throws IOException {
        Dem clean = SyntheticDems.metric(2, 2, 1, new float[] {1, 2, 3, 4});
        assertFalse(clean.knownAllFinite(), "not known before the statistics: no pass of its own");
        clean.statistics();
        assertTrue(clean.knownAllFinite());
        Dem holes = SyntheticDems.metric(2, 2, 1, new float[] {1, Float.NaN, 3, 4});
        holes.statistics();
        assertFalse(holes.knownAllFinite());
        Dem infinite = SyntheticDems.metric(2, 2, 1, new float[] {1, Float.POSITIVE_INFINITY, 3, 4});
        infinite.statistics();
        assertFalse(infinite.knownAllFinite());
        Files.writeString(tmp.resolve("f.hdr"), "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
                + "NODATA_value -9999\nbyteorder LSBFIRST\n");
        ByteBuffer b = ByteBuffer.allocate(16).order(ByteOrder.LITTLE_ENDIAN);
        b.putFloat(1).putFloat(2).putFloat(3).putFloat(4);
        Files.write(tmp.resolve("f.flt"), b.array());
        assertTrue(DemReader.read(tmp.resolve("f.flt")).knownAllFinite(), "a reader takes the statistics");
        b.clear();
        b.putFloat(1).putFloat(-9999).putFloat(3).putFloat(4);
        Files.write(tmp.resolve("f.flt"), b.array());
        assertFalse(DemReader.read(tmp.resolve("f.flt")).knownAllFinite(), "a no-data cell");
    }
}
