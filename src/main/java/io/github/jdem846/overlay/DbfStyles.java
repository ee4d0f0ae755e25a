package io.github.jdem846.overlay;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * The style fields of a shapefile's {@code .dbf} (dBASE III table: a 32-byte header, 32-byte field descriptors
 * ended by 0x0D, then fixed-width text records each led by a deletion flag): only the fields named as simplestyle
 * properties ({@link FeatureStyle}) are read, the rest skipped.
 */
final class DbfStyles {

    private static final Set<String> STYLE_FIELDS = Set.of("stroke", "stroke-width", "stroke-wid", "stroke-opacity",
            "stroke-opa", "fill", "fill-opacity", "fill-opaci", "marker-color", "marker-col", "marker-size",
            "marker-siz");

    private record Field(String name, int offset, int length) {
    }

    private DbfStyles() {
    }

    /**
     * @param shp     the {@code .shp} file; its {@code .dbf} is looked for beside it
     * @param records the number of records of the {@code .shp}
     * @return one style per record, or an empty list when there is no {@code .dbf} or it has no style field
     * @throws OverlayFileException when the {@code .dbf} is damaged, holds another number of records, or a style
     *                              value is not understood (naming the record)
     */
    static List<FeatureStyle> read(Path shp, int records) throws OverlayFileException {
        String base = shp.getFileName().toString();
        base = base.substring(0, base.length() - 4);
        Path dbf = shp.resolveSibling(base + ".dbf");
        if (!Files.isRegularFile(dbf)) {
            dbf = shp.resolveSibling(base + ".DBF");
            if (!Files.isRegularFile(dbf)) {
                return List.of();
            }
        }
        ByteBuffer b;
        try {
            b = ByteBuffer.wrap(Files.readAllBytes(dbf)).order(ByteOrder.LITTLE_ENDIAN);
        } catch (IOException | OutOfMemoryError e) {
            throw new OverlayFileException(dbf, "cannot be read (" + e.getMessage() + ")");
        }
        if (b.limit() < 33) {
            throw new OverlayFileException(dbf, "too short for a dBASE table (" + b.limit() + " bytes)");
        }
        int count = b.getInt(4);
        int headerLength = Short.toUnsignedInt(b.getShort(8));
        int recordLength = Short.toUnsignedInt(b.getShort(10));
        List<Field> fields = new ArrayList<>();
        int offset = 1;
        for (int at = 32; at + 32 <= headerLength && b.get(at) != 0x0D; at += 32) {
            int end = 0;
            while (end < 11 && b.get(at + end) != 0) {
                end++;
            }
            byte[] name = new byte[end];
            b.get(at, name);
            int length = Byte.toUnsignedInt(b.get(at + 16));
            String n = new String(name, StandardCharsets.ISO_8859_1).strip().toLowerCase(Locale.ROOT);
            if (STYLE_FIELDS.contains(n)) {
                fields.add(new Field(n, offset, length));
            }
            offset += length;
        }
        if (fields.isEmpty()) {
            return List.of();
        }
        if (count < 0 || recordLength < offset || (long) headerLength + (long) count * recordLength > b.limit()) {
            throw new OverlayFileException(dbf, "damaged dBASE table: " + count + " records of " + recordLength
                    + " bytes do not fit its " + b.limit() + " bytes");
        }
        if (count != records) {
            throw new OverlayFileException(dbf, "holds " + count + " records, its .shp " + records
                    + "; they must match one to one");
        }
        List<FeatureStyle> out = new ArrayList<>(count);
        Map<String, Object> values = new HashMap<>();
        for (int r = 0; r < count; r++) {
            int at = headerLength + r * recordLength;
            values.clear();
            for (Field f : fields) {
                byte[] text = new byte[f.length()];
                b.get(at + f.offset(), text);
                String value = new String(text, StandardCharsets.ISO_8859_1).strip();
                if (!value.matches("\\**")) { // blank or all asterisks: null (as shapelib writes a null number)
                    values.put(f.name(), value);
                }
            }
            try {
                out.add(FeatureStyle.of(new LinkedHashMap<>(values)));
            } catch (IllegalArgumentException e) {
                throw new OverlayFileException(dbf, "record " + (r + 1) + ": " + e.getMessage());
            }
        }
        return out;
    }
}
