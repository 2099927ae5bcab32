// @ts-check
// The first page a pupil sees in a class: their name, which picks their own folder. The studio
// answers with a cookie; the studio page (the same address) then opens in that folder.
import {join, who} from "./api.js";
import {translate} from "./classapi.js";
import {$, setWords} from "./page.js";

async function start() {
  const asked = await who();
  setWords(asked.strings);
  document.documentElement.lang = asked.language;
  translate(document);
  $("join").addEventListener("submit", /** @param {Event} event */ async event => {
    event.preventDefault();
    $("problem").textContent = "";
    try {
      await join({name: $("name").value});
      location.reload();   // the studio page, in this pupil's folder (?open= and ?language= stay)
    } catch (error) {
      $("problem").textContent = /** @type {Error} */ (error).message;
    }
  });
}

start().catch(error => { $("problem").textContent = error.message; });
