package io.github.jdem846.io.esri;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.source.MemoryGuard;
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
 * ESRI BIL ({@code .bil} + {@code .hdr}), read with the keys jDem846 read: {@code nbands}, {@code nbits},
 * {@code skipbytes}, {@code bandrowbytes}, {@code totalrowbytes}, {@code ulxmap}, {@code ulymap}, {@code xdim},
 * {@code ydim}, {@code NODATA}, {@code byteorder} and {@code pixeltype}. {@code ulxmap}/{@code ulymap} name the
 * centre of the upper-left cell (ESRI's definition). 16-bit signed or unsigned samples as in jDem846, plus 8-bit
 * and 32-bit integer or float; band 1 of a multi-band file, with a notice. Layout BIL (or any layout for one band).
 */
public final class BilFormat {

    private BilFormat() {
    }

    public static RasterSource open(Path bil) throws IOException {
        Path hdr = SidecarCrs.sibling(bil, "hdr");
        EsriHeader h = EsriHeader.read(hdr, "the BIL " + bil.getFileName() + " needs its header beside it, named "
                + hdr.getFileName());
        List<String> notices = new ArrayList<>();
        EsriGridLayout layout = EsriGridLayout.of(h, true, notices);
        int bands = h.has("nbands") ? h.positiveInt("nbands") : 1;
        int bits = h.has("nbits") ? h.positiveInt("nbits") : 8;
        String pixelType = h.string("pixeltype").orElse(bits == 32 ? "SIGNEDINT" : "UNSIGNEDINT")
                .toUpperCase(Locale.ROOT);
        SampleType type = sampleType(h, bits, pixelType);
        String layoutName = h.string("layout").orElse("BIL").toUpperCase(Locale.ROOT);
        if (bands > 1 && !layoutName.equals("BIL")) {
            throw new DemFormatException(hdr, "layout " + layoutName + " with " + bands
                    + " bands is not read; only BIL (band-interleaved by line) is");
        }
        if (bands > 1) {
            notices.add("the file has " + bands + " bands; band 1 is read");
        }
        ByteOrder order = GridFloatFormat.byteOrder(h, notices);
        long skip = h.nonNegativeLong("skipbytes", 0);
        long bandRowBytes = h.nonNegativeLong("bandrowbytes", (long) layout.cols() * type.bytes());
        long totalRowBytes = h.nonNegativeLong("totalrowbytes", 0);
        if (!h.has("totalrowbytes")) {
            if (MemoryGuard.saturatedMultiply(bands, bandRowBytes) == Long.MAX_VALUE) {
                throw new DemFormatException(hdr, "nbands " + bands + " × bandrowbytes " + bandRowBytes
                        + " makes rows of more than 8 EiB");
            }
            totalRowBytes = bands * bandRowBytes;
        }
        if (bandRowBytes < (long) layout.cols() * type.bytes() || totalRowBytes < bandRowBytes) {
            throw new DemFormatException(hdr, "bandrowbytes " + bandRowBytes + " / totalrowbytes " + totalRowBytes
                    + " are too small for " + layout.cols() + " columns of " + bits + " bits");
        }
        // exact: header values can make this pass Long.MAX_VALUE; when it fits in the file, every row offset fits
        BigInteger needed = BigInteger.valueOf(layout.rows() - 1L).multiply(BigInteger.valueOf(totalRowBytes))
                .add(BigInteger.valueOf(skip)).add(BigInteger.valueOf((long) layout.cols() * type.bytes()));
        long actual = Files.size(bil);
        if (BigInteger.valueOf(actual).compareTo(needed) < 0) {
            throw new DemFormatException(bil, "is " + actual + " bytes but the header needs at least " + needed
                    + " (skipbytes " + skip + " + " + layout.rows() + " rows of " + totalRowBytes + " bytes)");
        }
        Double noData = h.firstNumber("nodata", "nodata_value").orElse(null);
        CrsInfo crs = SidecarCrs.resolve(bil, layout, notices);
        GridGeometry g = ReaderGeometry.of(hdr, "the header's keys", layout.cols(), layout.rows(),
                layout.originX(), layout.originY(), layout.cellWidth(), layout.cellHeight(), crs, layout.anchor());
        DemInfo info = new DemInfo(bil.toString(), DemFormat.BIL, type, bands, g, noData, notices);
        return new RawRasterSource(info, bil, skip, totalRowBytes, type, order);
    }

    private static SampleType sampleType(EsriHeader h, int bits, String pixelType) throws DemFormatException {
        boolean signed = pixelType.startsWith("SIGNED");
        boolean isFloat = pixelType.equals("FLOAT");
        if (!signed && !isFloat && !pixelType.equals("UNSIGNEDINT")) {
            throw new DemFormatException(h.file(), "header key 'pixeltype' is '" + pixelType
                    + "', not SIGNEDINT, UNSIGNEDINT or FLOAT");
        }
        return switch (bits) {
            case 8 -> signed ? SampleType.INT8 : SampleType.UINT8;
            case 16 -> signed ? SampleType.INT16 : SampleType.UINT16;
            case 32 -> isFloat ? SampleType.FLOAT32 : signed ? SampleType.INT32 : SampleType.UINT32;
            default -> throw new DemFormatException(h.file(), "header key 'nbits' is " + bits
                    + "; only 8, 16 or 32 bits per sample are read");
        };
    }
}
