// What the studio's browser tests share: starting `insula studio` and reading its URL, and
// waiting for the page's next finished build.
import { spawn } from 'node:child_process';

// Starts `insula studio FOLDER`; resolves to { server, url } once it prints its URL.
export async function startStudio(insula, folder) {
  const server = spawn(insula, ['studio', folder], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (chunk) => {
      text += chunk;
      const m = /http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]+/.exec(text);
      if (m) resolve(m[0]);
    });
    server.on('exit', () => reject(new Error('the studio exited')));
    setTimeout(() => reject(new Error('no URL in 10 s')), 10000);
  });
  return { server, url };
}

// waitBuild(predicate, what, after): waits (60 s at most) for the page's last build to be the
// latest edit's, newer than sequence `after`, with `predicate` (the body of a function of the
// build's answer `b`) true; else records `what` and the answer in `failures`.
export function buildWaiter(page, failures) {
  return async (predicate, what, after = 0) => {
    try {
      await page.waitForFunction(([p, n]) => {
        const b = window.studio && window.studio.lastBuild;
        return b && b.sequence === window.studio.sequence && b.sequence > n && new Function('b', p)(b);
      }, [predicate, after], { timeout: 60000 });
    } catch {
      failures.push(`${what}: ${JSON.stringify(await page.evaluate(() => window.studio.lastBuild))}`.slice(0, 600));
    }
  };
}
