package io.github.jdem846.io.esri;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.io.source.RawRasterSource;
import io.github.jdem846.io.source.ReaderGeometry;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.math.BigInteger;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * ESRI GridFloat: a headerless {@code .flt} of float32 rows from north to south, described by the {@code .hdr}
 * beside it ({@code ncols}, {@code nrows}, {@code xllcorner|xllcenter}, {@code yllcorner|yllcenter},
 * {@code cellsize}, {@code NODATA_value}, {@code byteorder LSBFIRST|MSBFIRST|I|M}; keys case-insensitive) and
 * optionally a {@code .prj}. A missing {@code NODATA_value} means no no-data (jDem846 took 0, which turned sea
 * level into holes); a missing {@code byteorder} means MSBFIRST, as in jDem846 and GDAL, with a notice.
 */
public final class GridFloatFormat {

    private GridFloatFormat() {
    }

    public static RasterSource open(Path flt) throws IOException {
        Path hdr = SidecarCrs.sibling(flt, "hdr");
        EsriHeader h = EsriHeader.read(hdr, "the GridFloat " + flt.getFileName() + " needs its header beside it,"
                + " named " + hdr.getFileName());
        List<String> notices = new ArrayList<>();
        EsriGridLayout layout = EsriGridLayout.of(h, false, notices);
        ByteOrder order = byteOrder(h, notices);
        Double noData = h.firstNumber("nodata_value", "nodata").orElse(null);

        // exact: ncols × nrows × 4 can pass Long.MAX_VALUE
        BigInteger expected = BigInteger.valueOf(layout.cols()).multiply(BigInteger.valueOf(layout.rows()))
                .multiply(BigInteger.valueOf(4));
        long actual = Files.size(flt);
        if (!expected.equals(BigInteger.valueOf(actual))) {
            throw new DemFormatException(flt, "is " + actual + " bytes but the header's ncols × nrows × 4 = "
                    + layout.cols() + " × " + layout.rows() + " × 4 = " + expected + " bytes");
        }
        CrsInfo crs = SidecarCrs.resolve(flt, layout, notices);
        GridGeometry g = ReaderGeometry.of(hdr, "the header's keys", layout.cols(), layout.rows(),
                layout.originX(), layout.originY(), layout.cellWidth(), layout.cellHeight(), crs, layout.anchor());
        DemInfo info = new DemInfo(flt.toString(), DemFormat.GRIDFLOAT, SampleType.FLOAT32, 1, g, noData, notices);
        return new RawRasterSource(info, flt, 0, (long) layout.cols() * 4, SampleType.FLOAT32, order);
    }

    /** {@code byteorder}/{@code BYTEORDER}: LSBFIRST, I, MSBFIRST, M (MSBFIRST when missing, with a notice). */
    static ByteOrder byteOrder(EsriHeader h, List<String> notices) throws DemFormatException {
        String v = h.string("byteorder").orElse(null);
        if (v == null) {
            notices.add("no byteorder in the header: MSBFIRST assumed (ESRI's default)");
            return ByteOrder.BIG_ENDIAN;
        }
        return switch (v.toUpperCase(Locale.ROOT)) {
            case "LSBFIRST", "I", "LSB", "INTEL" -> ByteOrder.LITTLE_ENDIAN;
            case "MSBFIRST", "M", "MSB", "MOTOROLA" -> ByteOrder.BIG_ENDIAN;
            default -> throw new DemFormatException(h.file(), "header key 'byteorder' is '" + v
                    + "', not LSBFIRST, MSBFIRST, I or M");
        };
    }
}
