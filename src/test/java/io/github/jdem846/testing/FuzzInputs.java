package io.github.jdem846.testing;

import io.github.jdem846.io.DemFormatException;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.Stream;

/**
 * What every fuzz test of a reader checks: the input, written to a file, reads to a value or is refused with the
 * reader's own exception naming the file; anything else (a JDK runtime exception, an error, an allocation far
 * beyond what the input can justify) is a finding. Jazzer reports the exception when fuzzing; the regression run
 * of the normal tests fails with it.
 */
public final class FuzzInputs {

    /**
     * The most a read may allocate beyond {@link #BYTES_PER_INPUT_BYTE} per input byte: room for the decoders'
     * own buffers and a small grid. A compressed input can justify about a thousand times its size (Deflate's
     * limit is 1032:1); a header alone justifies nothing.
     */
    public static final long BASE_ALLOCATION = 96L << 20;
    /** Bytes a read may allocate per byte of input (above Deflate's and LZW's ratios, with the float grid). */
    public static final long BYTES_PER_INPUT_BYTE = 16_384;

    private static final Path DIR = newDirectory();
    private static final Method ALLOCATED = allocatedBytesMethod();

    /** A read of a fuzzed file. */
    @FunctionalInterface
    public interface Read {
        /**
         * Reads the file.
         *
         * @throws Exception what the reader throws
         */
        void run() throws Exception;
    }

    private FuzzInputs() {
    }

    /**
     * Writes the input to a file of the name given, in a directory of its own for this JVM (removed at exit).
     *
     * @param name the file name (its extension picks the reader)
     * @param data the content
     * @return the file
     */
    public static Path write(String name, byte[] data) {
        try {
            return Files.write(DIR.resolve(name), data);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Runs the read: a value, or a {@link DemFormatException} whose message starts with the file or a sidecar
     * of it (same name, another extension), pass; another exception propagates; a message naming another file,
     * or an allocation above {@link #BASE_ALLOCATION} + {@link #BYTES_PER_INPUT_BYTE} per input byte, fails.
     *
     * @param file       the input file
     * @param inputBytes the size of the fuzzed input
     * @param read       the read
     * @throws Exception what the reader threw, if not a well-formed refusal
     */
    public static void readsOrRefuses(Path file, long inputBytes, Read read) throws Exception {
        readsOrRefuses(List.of(file), inputBytes, read);
    }

    /**
     * Like {@link #readsOrRefuses(Path, long, Read)}, when a refusal may name any of several files (a mosaic and
     * its members).
     *
     * @param files      the files a refusal may name (the first is the input)
     * @param inputBytes the size of the fuzzed input
     * @param read       the read
     * @throws Exception what the reader threw, if not a well-formed refusal
     */
    public static void readsOrRefuses(List<Path> files, long inputBytes, Read read) throws Exception {
        readsOrRefuses(e -> namesOneOf(files, e), inputBytes, read);
    }

    /**
     * Like {@link #readsOrRefuses(Path, long, Read)}, with the check of a refusal given.
     *
     * @param refusal    checks a refusal, throwing an AssertionError when it is not well-formed
     * @param inputBytes the size of the fuzzed input
     * @param read       the read
     * @throws Exception what the reader threw, if not a well-formed refusal
     */
    public static void readsOrRefuses(Consumer<DemFormatException> refusal, long inputBytes, Read read)
            throws Exception {
        long limit = BASE_ALLOCATION + BYTES_PER_INPUT_BYTE * inputBytes;
        long allocated = readOnce(refusal, read);
        if (allocated > limit) {
            // the first read in a JVM also pays for one-time set-up (class loading, Apache SIS's EPSG tables)
            allocated = readOnce(refusal, read);
        }
        if (allocated > limit) {
            throw new AssertionError("reading " + inputBytes + " bytes allocated " + allocated
                    + " bytes, more than " + limit);
        }
    }

    /** Runs the read, checks a refusal, and returns the bytes it allocated (-1 where not known). */
    private static long readOnce(Consumer<DemFormatException> refusal, Read read) throws Exception {
        long before = allocatedBytes();
        try {
            read.run();
        } catch (DemFormatException e) {
            refusal.accept(e);
        }
        long after = allocatedBytes();
        return before < 0 || after < 0 ? -1 : after - before;
    }

    private static void namesOneOf(List<Path> files, DemFormatException e) {
        AssertionError first = null;
        for (Path f : files) {
            try {
                namesTheFile(f, e.getMessage());
                return;
            } catch (AssertionError a) {
                first = first != null ? first : a;
            }
        }
        first.initCause(e);
        throw first;
    }

    /**
     * Fails unless the message starts with the file or a sidecar of it, then states a problem.
     *
     * @param file    the input file
     * @param message the refusal's message
     */
    public static void namesTheFile(Path file, String message) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = file.resolveSibling(dot > 0 ? name.substring(0, dot) : name).toString();
        if (message == null || !(message.startsWith(file.toString()) || message.startsWith(base + "."))) {
            throw new AssertionError("the refusal does not start with the file " + file + ": " + message);
        }
        if (message.length() < file.toString().length() + 10) {
            throw new AssertionError("the refusal states no problem: " + message);
        }
    }

    /** Bytes allocated by this thread so far (HotSpot's counter), or -1 where the JVM has none. */
    private static long allocatedBytes() {
        if (ALLOCATED == null) {
            return -1;
        }
        try {
            return (long) ALLOCATED.invoke(ManagementFactory.getThreadMXBean());
        } catch (ReflectiveOperationException | RuntimeException e) {
            return -1;
        }
    }

    private static Method allocatedBytesMethod() {
        try {
            Class<?> bean = Class.forName("com.sun.management.ThreadMXBean");
            if (!bean.isInstance(ManagementFactory.getThreadMXBean())) {
                return null;
            }
            return bean.getMethod("getCurrentThreadAllocatedBytes");
        } catch (ReflectiveOperationException | RuntimeException e) {
            return null;
        }
    }

    private static Path newDirectory() {
        try {
            Path dir = Files.createTempDirectory("jdem846-fuzz");
            Runtime.getRuntime().addShutdownHook(new Thread(() -> deleteTree(dir)));
            return dir;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static void deleteTree(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException ignored) {
            // a temporary directory left behind
        }
    }
}
