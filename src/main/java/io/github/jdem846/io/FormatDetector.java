package io.github.jdem846.io;

import io.github.jdem846.io.esri.SidecarCrs;
import io.github.jdem846.io.source.RegularFiles;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Which format a file is, from its first bytes (TIFF and BigTIFF magic numbers, an ASCII grid's {@code ncols}, a
 * GDAL VRT's {@code <VRTDataset}) and its extension ({@code .flt}, {@code .bil}, {@code .hgt}, {@code .asc},
 * {@code .vrt}; a {@code .hdr} stands for the
 * {@code .flt} or {@code .bil} beside it). Also refuses what is not a DEM file: missing, a directory, a FIFO or
 * device (before opening it, which could block), empty.
 */
final class FormatDetector {

    /** A format and the file that holds its data (a {@code .hdr} given by the user resolves to its data file). */
    record Detected(DemFormat format, Path dataFile) {
    }

    private FormatDetector() {
    }

    static Detected detect(Path file) throws DemFormatException {
        if (Files.isDirectory(file)) {
            throw new DemFormatException(file, "is a directory, not a DEM file");
        }
        if (!Files.exists(file)) {
            throw new DemFormatException(file, "no such file");
        }
        // before anything opens it: a FIFO without a writer or a character device would block the read
        RegularFiles.require(file, "a DEM");
        if (!Files.isReadable(file)) {
            throw new DemFormatException(file, "cannot be read (permission denied)");
        }
        String ext = SidecarCrs.extension(file);
        if (ext.equals("hdr")) {
            for (String dataExt : new String[] {"flt", "bil"}) {
                Path data = SidecarCrs.sibling(file, dataExt);
                if (Files.exists(data)) {
                    return detect(data);
                }
            }
            throw new DemFormatException(file, "is a header; give the .flt or .bil file it describes (none was"
                    + " found beside it)");
        }
        byte[] head = head(file);
        if (head.length == 0) {
            throw new DemFormatException(file, "is empty (0 bytes)");
        }
        if (isTiff(head)) {
            return new Detected(DemFormat.GEOTIFF, file);
        }
        String start = new String(head, StandardCharsets.ISO_8859_1);
        if (ext.equals("vrt") || start.contains("<VRTDataset")) {
            if (!start.stripLeading().startsWith("<") && !start.startsWith("\u00ef\u00bb\u00bf<")) {
                throw new DemFormatException(file, "is named .vrt but is not a GDAL VRT: it is not XML"
                        + " (a VRT starts with <VRTDataset)");
            }
            return new Detected(DemFormat.VRT, file);
        }
        switch (ext) {
            case "tif", "tiff", "gtif" -> throw new DemFormatException(file, "is named ." + ext
                    + " but is not a TIFF: it does not start with II*\\0, MM\\0*, II+\\0 or MM\\0+");
            case "flt" -> {
                return new Detected(DemFormat.GRIDFLOAT, file);
            }
            case "bil" -> {
                return new Detected(DemFormat.BIL, file);
            }
            case "hgt" -> {
                return new Detected(DemFormat.SRTM_HGT, file);
            }
            default -> {
                // by content below
            }
        }
        String text = new String(head, StandardCharsets.ISO_8859_1).stripLeading().toLowerCase(Locale.ROOT);
        if (text.startsWith("ncols") || text.startsWith("nrows")) {
            return new Detected(DemFormat.ESRI_ASCII, file);
        }
        if (ext.equals("asc")) {
            throw new DemFormatException(file, "is named .asc but is not an ESRI ASCII grid: it does not start"
                    + " with 'ncols'");
        }
        throw new DemFormatException(file, "is not a DEM format this program reads: expected GeoTIFF (.tif),"
                + " ESRI GridFloat (.flt + .hdr), ESRI ASCII grid (.asc), ESRI BIL (.bil + .hdr), SRTM (.hgt) or a"
                + " GDAL VRT (.vrt)");
    }

    private static byte[] head(Path file) throws DemFormatException {
        try (InputStream in = Files.newInputStream(file)) {
            return in.readNBytes(64);
        } catch (IOException e) {
            throw new DemFormatException(file, "cannot be read: " + e.getMessage(), e);
        }
    }

    private static boolean isTiff(byte[] h) {
        if (h.length < 4) {
            return false;
        }
        boolean ii = h[0] == 'I' && h[1] == 'I' && (h[2] == 42 || h[2] == 43) && h[3] == 0;
        boolean mm = h[0] == 'M' && h[1] == 'M' && h[2] == 0 && (h[3] == 42 || h[3] == 43);
        return ii || mm;
    }
}
